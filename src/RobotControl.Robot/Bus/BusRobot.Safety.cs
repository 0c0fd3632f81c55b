namespace RobotControl.Robot.Bus;

/// <summary>
/// What the write path enforces for a safety supervisor: the step cap (no motor goal moves further in one write than
/// its maximum speed times the time since the previous write; enforced and counted), the hold (goals frozen at the
/// measured positions, setpoints ignored) and a hook that runs at the end of every <see cref="Update"/>.
/// </summary>
public sealed partial class BusRobot
{
    private const double StepCapToleranceRad = 1e-9;
    private double[] _sentGoals = [];
    private double[] _heldGoals = [];
    private bool _capPrimed;
    private volatile int _hold; // 0: none, 1: asked (captured at the next write), 2: holding
    private long _stepCapHits;
    private double _largestCappedStepRad;

    /// <summary>
    /// Runs at the end of every <see cref="Update"/> on the bus's thread (the cycle's point between read and write):
    /// the safety supervisor's per-cycle checks. Must not allocate or block.
    /// </summary>
    public Action? AfterUpdate { get; set; }

    /// <summary>Goals the step cap shortened so far (one per motor and write).</summary>
    public long StepCapHits => Interlocked.Read(ref _stepCapHits);

    /// <summary>The largest step asked of a motor in one write that the cap shortened, output radians (0: none).</summary>
    public double LargestCappedStepRad => Volatile.Read(ref _largestCappedStepRad);

    /// <summary>True while the goals are frozen at the measured positions (<see cref="HoldAtMeasured"/>).</summary>
    public bool IsHolding => _hold != 0;

    /// <summary>Teleoperation drives the arms only while nothing holds them (<see cref="IsHolding"/>): see <see cref="RobotControl.Robot.Control.IRobotPort.TeleopAllowed"/>.</summary>
    public bool TeleopAllowed => _hold == 0;

    /// <summary>
    /// Freezes every motor's goal at its measured position from the next write on; the joint setpoints are ignored
    /// until <see cref="ReleaseHold"/>.
    /// </summary>
    public void HoldAtMeasured() => Interlocked.CompareExchange(ref _hold, 1, 0);

    /// <summary>The setpoints drive the goals again (each still under the step cap).</summary>
    public void ReleaseHold() => _hold = 0;

    /// <summary>The goal last sent to <paramref name="motor"/>, output radians (its position before the first write).</summary>
    public double SentGoalRad(RobotMotor motor)
    {
        ArgumentNullException.ThrowIfNull(motor);
        return _sentGoals.Length > motor.Index ? _sentGoals[motor.Index] : motor.PositionRad;
    }

    /// <summary>The step cap of <paramref name="motor"/> over <paramref name="seconds"/>: its maximum output speed times the time, radians.</summary>
    public static double StepCapRad(RobotMotor motor, double seconds)
    {
        ArgumentNullException.ThrowIfNull(motor);
        return motor.SpeedLimitRadS * seconds;
    }

    /// <summary>Applies the hold and the step cap to the goals <see cref="ComputeGoals"/> made, and remembers what is sent.</summary>
    private void CapAndHoldGoals(double dt)
    {
        if (_sentGoals.Length != _goals.Length)
        {
            _sentGoals = new double[_goals.Length];
            _heldGoals = new double[_goals.Length];
        }

        if (_hold == 1)
        {
            foreach (var m in _motors)
            {
                _heldGoals[m.Index] = Math.Clamp(m.PositionRad, m.Config.OutputMinRad, m.Config.OutputMaxRad);
            }

            Interlocked.CompareExchange(ref _hold, 2, 1);
        }

        var holding = _hold == 2;
        foreach (var m in _motors)
        {
            var i = m.Index;
            var goal = holding && _torqueEnabled ? _heldGoals[i] : _goals[i];
            if (_capPrimed && _torqueEnabled && dt > 0)
            {
                var cap = StepCapRad(m, dt);
                var step = goal - _sentGoals[i];
                if (Math.Abs(step) > cap + StepCapToleranceRad)
                {
                    goal = _sentGoals[i] + Math.CopySign(cap, step);
                    Interlocked.Increment(ref _stepCapHits);
                    if (Math.Abs(step) > _largestCappedStepRad)
                    {
                        Volatile.Write(ref _largestCappedStepRad, Math.Abs(step));
                    }
                }
            }

            _goals[i] = goal;
            _sentGoals[i] = goal;
        }

        _capPrimed = true;
    }
}
