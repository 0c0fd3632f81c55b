using RobotControl.Modules;

namespace RobotControl.Robot.Bus;

/// <summary>
/// One motor: named after its joint, with its gear ratio, limits and gain (kept in the module's FRAM), manual jog and
/// setpoint, and two outputs: position (radians at the axis output) and filtered current (A). Manual commands
/// override the arm's joint setpoints for this motor until <see cref="ReleaseManual"/>. Its state is written by the
/// bus thread (the feedback, and the manual commands, which run between cycles); any thread reads it, and the control
/// loop asks a manual motor to hold through <see cref="RequestHold"/>, taken up at the next write.
/// </summary>
[WrittenBy(RobotThread.Bus)]
public sealed class RobotMotor
{
    private double _position;
    private double _current;
    private double _manualSetpoint = double.NaN;
    private double _potPosition = double.NaN;
    private double _positionAtPot = double.NaN;
    private double _jogRate;
    private int _manual;
    private int _holdRequested;
    private int _pwm;
    private int _torque = -1;
    private int _errors = -1;
    private PotCalibrationTable _potCalibration;

    internal RobotMotor(MotorConfig config, RobotController controller, int index)
    {
        Config = config;
        _potCalibration = PotCalibrationTable.For(config);
        Controller = controller;
        Index = index;
    }

    /// <summary>The motor's configuration (names, ratio, limits, conversions).</summary>
    public MotorConfig Config { get; }

    /// <summary>The module driving it.</summary>
    public RobotController Controller { get; }

    /// <summary>Joint name (or the tool drive's name).</summary>
    public string Name => Config.Name;

    /// <summary>Total reduction motor to axis output.</summary>
    public double GearRatio => Config.GearRatio;

    /// <summary>Current limit, A.</summary>
    public double CurrentLimitA => Config.Motor.CurrentLimitA;

    /// <summary>Speed limit at the axis output, rad/s.</summary>
    public double SpeedLimitRadS => Config.Motor.SpeedLimitRadS;

    /// <summary>Proportional gain, PWM duty per radian of output error.</summary>
    public double Kp => Config.Motor.Kp;

    /// <summary>Output: latest axis output angle, radians.</summary>
    public double PositionRad => Volatile.Read(ref _position);

    /// <summary>Output: latest filtered motor current, A.</summary>
    public double CurrentA => Volatile.Read(ref _current);

    /// <summary>True while a manual setpoint or jog drives this motor.</summary>
    public bool IsManual => Volatile.Read(ref _manual) != 0;

    internal int Index { get; }

    /// <summary>Moves the motor to <paramref name="outputRad"/> (limited to its range), overriding the arm's setpoints.</summary>
    /// <exception cref="ArgumentException">The value is not finite.</exception>
    public void SetSetpoint(double outputRad)
    {
        if (!double.IsFinite(outputRad))
        {
            throw new ArgumentException("a motor setpoint must be finite", nameof(outputRad));
        }

        Volatile.Write(ref _jogRate, 0);
        Volatile.Write(ref _manualSetpoint, Math.Clamp(outputRad, Config.OutputMinRad, Config.OutputMaxRad));
        Volatile.Write(ref _manual, 1);
    }

    /// <summary>Jogs the motor at <paramref name="outputRadPerS"/> (limited to its speed limit) from where it is; 0 stops.</summary>
    /// <exception cref="ArgumentException">The value is not finite.</exception>
    public void Jog(double outputRadPerS)
    {
        if (!double.IsFinite(outputRadPerS))
        {
            throw new ArgumentException("a jog speed must be finite", nameof(outputRadPerS));
        }

        if (!IsManual)
        {
            Volatile.Write(ref _manualSetpoint, PositionRad);
        }

        Volatile.Write(ref _jogRate, Math.Clamp(outputRadPerS, -SpeedLimitRadS, SpeedLimitRadS));
        Volatile.Write(ref _manual, 1);
    }

    /// <summary>A manual motor stops where it is at the next write (any thread: the loop's hold after a plug-in fault).</summary>
    public void RequestHold() => Volatile.Write(ref _holdRequested, 1);

    /// <summary>The PWM the module applies, of 255, from the latest feedback.</summary>
    public int Pwm => Volatile.Read(ref _pwm);

    /// <summary>Torque as the module last read it back (null: not read yet, or it did not answer).</summary>
    public bool? TorqueReadBack => Volatile.Read(ref _torque) switch { < 0 => null, var t => t != 0 };

    /// <summary>The motor's latched errors as its module last reported them (null: not read yet, or it did not answer).</summary>
    public HardwareErrors? Errors => Volatile.Read(ref _errors) is var e and >= 0 ? (HardwareErrors)(long)e : null;

    /// <summary>Returns the motor to the arm's joint setpoints.</summary>
    public void ReleaseManual()
    {
        Volatile.Write(ref _jogRate, 0);
        Volatile.Write(ref _manual, 0);
    }

    /// <inheritdoc />
    public override string ToString() => Config.ToString();

    /// <summary>The manual goal for this cycle (advancing a jog by <paramref name="dt"/> seconds).</summary>
    internal double ManualGoal(double dt)
    {
        if (Volatile.Read(ref _holdRequested) != 0 && Interlocked.Exchange(ref _holdRequested, 0) != 0)
        {
            Volatile.Write(ref _jogRate, 0);
            Volatile.Write(ref _manualSetpoint, Math.Clamp(PositionRad, Config.OutputMinRad, Config.OutputMaxRad));
        }

        var goal = Volatile.Read(ref _manualSetpoint);
        var rate = Volatile.Read(ref _jogRate);
        if (rate != 0)
        {
            goal = Math.Clamp(goal + (rate * dt), Config.OutputMinRad, Config.OutputMaxRad);
            Volatile.Write(ref _manualSetpoint, goal);
        }

        return goal;
    }

    /// <summary>
    /// The position the joint pot reads, output radians, through the calibration its module holds as homing last read it
    /// (a unit's own after <c>robotctl calibrate pots</c>; the robot file's design curve before homing); NaN before the first pot poll (<see cref="BusRobotOptions.PotPollCycles"/>) or
    /// without a pot calibration.
    /// </summary>
    public double PotPositionRad => Volatile.Read(ref _potPosition);

    /// <summary>
    /// The encoder position published when the pot was last read (<see cref="PotPositionRad"/>), output radians: the
    /// pot/encoder check compares readings of one instant, not a pot reading a poll old against a moving encoder.
    /// </summary>
    public double PositionAtPotRad => Volatile.Read(ref _positionAtPot);

    /// <summary>The pot calibration its module holds (homing reads it there): the pot/encoder check uses the module's own table.</summary>
    internal void UsePotCalibration(PotCalibrationTable table) => _potCalibration = table;

    internal void PublishPot(int raw)
    {
        if (_potCalibration.IsCalibrated)
        {
            Volatile.Write(ref _positionAtPot, Volatile.Read(ref _position));
            Volatile.Write(ref _potPosition, Config.ToRadians(_potCalibration.PositionAt(raw)));
        }
    }

    internal void PublishTorque(bool? on) => Volatile.Write(ref _torque, on is null ? -1 : on.Value ? 1 : 0);

    internal void PublishErrors(HardwareErrors? errors) => Volatile.Write(ref _errors, errors is { } e ? e.Value : -1);

    internal void Publish(double positionRad, double currentA, int pwm)
    {
        Volatile.Write(ref _pwm, pwm);
        Publish(positionRad, currentA);
    }

    internal void Publish(double positionRad, double currentA)
    {
        Volatile.Write(ref _position, positionRad);
        Volatile.Write(ref _current, currentA);
    }
}
