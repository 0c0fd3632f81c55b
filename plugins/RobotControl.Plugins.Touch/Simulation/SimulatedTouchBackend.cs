using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Faults;
using RobotControl.Plugins.Touch.Backends;

namespace RobotControl.Plugins.Touch.Simulation;

/// <summary>
/// A simulated Touch: a hand follows a <see cref="HandScript"/> holding the stylus through a <see cref="HandModel"/>,
/// so forces sent to the device visibly push the handle. Runs on the loop thread from the tick time: deterministic.
/// Takes the injected device faults (<see cref="IFaultInjectable"/>): a jump of the reading and stale readings.
/// </summary>
public sealed class SimulatedTouchBackend : ITouchBackend, IFaultInjectable
{
    private readonly HandScript _script;
    private readonly HandModel _hand;
    private readonly double _maxForceN;
    private readonly double _timeOffset;
    private readonly bool _repeat;
    private readonly double[] _pose = new double[6];
    private readonly double[] _handVelocity = new double[3];
    private double _lastTime = double.NaN;
    private int _hint;
    private double _jumpXMm;
    private double _frozenAt = double.NaN;
    private TouchSample _last;

    /// <summary>Creates the back end.</summary>
    public SimulatedTouchBackend(HandScript script, HandModel hand, double maxForceN, double timeOffsetSeconds = 0, bool repeat = false)
    {
        ArgumentNullException.ThrowIfNull(script);
        ArgumentNullException.ThrowIfNull(hand);
        _script = script;
        _hand = hand;
        _maxForceN = maxForceN;
        _timeOffset = timeOffsetSeconds;
        _repeat = repeat;
    }

    /// <summary>The back end a validated <see cref="TouchSettings"/> describes (loads the script).</summary>
    internal static SimulatedTouchBackend Create(TouchSettings settings, PluginContext context)
    {
        var script = HandScript.Load(context.ResolvePath(settings.Script), settings.RecordingPrefix);
        var hand = new HandModel(settings.HandMassKg, settings.HandStiffnessNPerMm, settings.HandDampingNsPerMm);
        return new SimulatedTouchBackend(script, hand, settings.MaxForceN, settings.TimeOffsetS, settings.Repeat);
    }

    /// <inheritdoc />
    public string Description => $"simulated Touch ({_script.Count} keyframes, {_script.DurationSeconds:0.###} s)";

    /// <summary>The hand model (for tests and displays).</summary>
    public HandModel Hand => _hand;

    /// <summary>The force that pushed the hand on the last exchange, N (zero while <c>force_enable</c> is off).</summary>
    public (double XN, double YN, double ZN) LastRenderedForce { get; private set; }

    /// <summary>
    /// Fault injection: from the next exchange on, every reading is <paramref name="xMm"/> further along x than the hand
    /// (an input jump in one sample: a glitch of the encoders, a stylus knocked). Adds to earlier jumps.
    /// </summary>
    public void Jump(double xMm)
    {
        if (!double.IsFinite(xMm))
        {
            throw new ArgumentOutOfRangeException(nameof(xMm), xMm, "the jump must be finite");
        }

        _jumpXMm += xMm;
    }

    /// <summary>
    /// Fault injection: the device stops giving new readings (a cable pulled, a driver hung): every exchange from the
    /// next one on returns the last reading, its <see cref="TouchSample.AgeMs"/> growing with loop time.
    /// </summary>
    public void Freeze()
    {
        if (double.IsNaN(_frozenAt))
        {
            _frozenAt = double.IsNaN(_lastTime) ? 0 : _lastTime;
        }
    }

    /// <inheritdoc />
    public bool CanTake(DeviceFaultKind kind) => kind is DeviceFaultKind.Jump or DeviceFaultKind.Stale;

    /// <inheritdoc />
    public void Inject(DeviceFault fault)
    {
        ArgumentNullException.ThrowIfNull(fault);
        switch (fault.Kind)
        {
            case DeviceFaultKind.Jump:
                Jump(fault.JumpXMm);
                break;
            case DeviceFaultKind.Stale:
                Freeze();
                break;
            default:
                throw new ArgumentException($"a simulated Touch cannot take a {fault} fault", nameof(fault));
        }
    }

    /// <inheritdoc />
    public void Open()
    {
        _lastTime = double.NaN;
        _hint = 0;
    }

    /// <inheritdoc />
    public TouchSample Exchange(double timeSeconds, in TouchForce force)
    {
        if (!double.IsNaN(_frozenAt))
        {
            LastRenderedForce = (0, 0, 0); // nothing reaches a device that does not answer
            return _last with { AgeMs = (timeSeconds - _frozenAt) * 1e3 };
        }

        var t = ScriptTime(timeSeconds + _timeOffset);
        _script.Sample(t, _pose, _handVelocity, out var button1, out var button2, ref _hint);
        if (double.IsNaN(_lastTime))
        {
            _hand.Reset(_pose);
        }
        else
        {
            var (fx, fy, fz) = Limit(force);
            LastRenderedForce = (fx, fy, fz);
            _hand.Step(timeSeconds - _lastTime, _pose, _handVelocity, fx, fy, fz);
        }

        _lastTime = timeSeconds;
        var p = _hand.Position;
        _last = new TouchSample(p[0] + _jumpXMm, p[1], p[2], _pose[3], _pose[4], _pose[5], button1, button2);
        return _last;
    }

    /// <inheritdoc />
    public void Dispose()
    {
    }

    private double ScriptTime(double t) =>
        _repeat && t > _script.DurationSeconds ? t % _script.DurationSeconds : t;

    private (double X, double Y, double Z) Limit(in TouchForce force)
    {
        // Force disabled (run level), non-finite or excessive: none, none, scaled down.
        if (!force.Enabled || !double.IsFinite(force.XN) || !double.IsFinite(force.YN) || !double.IsFinite(force.ZN))
        {
            return (0, 0, 0);
        }

        var magnitude = Math.Sqrt((force.XN * force.XN) + (force.YN * force.YN) + (force.ZN * force.ZN));
        var scale = magnitude > _maxForceN ? _maxForceN / magnitude : 1.0;
        return (force.XN * scale, force.YN * scale, force.ZN * scale);
    }
}
