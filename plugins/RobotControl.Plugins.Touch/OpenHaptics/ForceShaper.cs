namespace RobotControl.Plugins.Touch.OpenHaptics;

/// <summary>
/// Turns the loop's latest force into the force one servo frame sends: zero while the loop's command is stale (not
/// renewed for <c>staleFrames</c> frames, or never given) or the run level forbids force, or it is not finite;
/// otherwise clamped to <c>maxForceN</c> in magnitude (direction kept) and ramped in linearly over
/// <c>rampFrames</c> frames whenever force output (re)starts. Runs on the servo thread; allocation-free.
/// </summary>
internal sealed class ForceShaper
{
    private readonly double _maxForceN;
    private readonly double _rampStep;
    private readonly int _staleFrames;
    private long _lastSequence;
    private int _age;

    public ForceShaper(double maxForceN, int rampFrames, int staleFrames)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(maxForceN);
        ArgumentOutOfRangeException.ThrowIfNegative(rampFrames);
        ArgumentOutOfRangeException.ThrowIfLessThan(staleFrames, 1);
        _maxForceN = maxForceN;
        _rampStep = rampFrames == 0 ? 1.0 : 1.0 / rampFrames;
        _staleFrames = staleFrames;
    }

    /// <summary>The ramp factor of the last frame (0: no force).</summary>
    public double Scale { get; private set; }

    /// <summary>The force for this frame into <paramref name="force"/> (three values).</summary>
    public void Next(in ServoCommand command, bool haveCommand, Span<double> force)
    {
        if (haveCommand && command.Sequence != _lastSequence)
        {
            _lastSequence = command.Sequence;
            _age = 0;
        }
        else if (_age < int.MaxValue)
        {
            _age++;
        }

        var fresh = haveCommand && command.Sequence != 0 && _age < _staleFrames;
        var finite = double.IsFinite(command.XN) && double.IsFinite(command.YN) && double.IsFinite(command.ZN);
        if (!fresh || !command.Enabled || !finite)
        {
            Scale = 0;
            force[..3].Clear();
            return;
        }

        Scale = Math.Min(1.0, Scale + _rampStep);
        var magnitude = Math.Sqrt((command.XN * command.XN) + (command.YN * command.YN) + (command.ZN * command.ZN));
        var k = Scale * (magnitude > _maxForceN ? _maxForceN / magnitude : 1.0);
        force[0] = command.XN * k;
        force[1] = command.YN * k;
        force[2] = command.ZN * k;
    }
}
