namespace RobotControl.Robot.Calibration;

/// <summary>How a pot calibration moves and what it accepts (<see cref="PotCalibrator"/>).</summary>
public sealed record PotCalibrationOptions
{
    /// <summary>Sweep speed as a fraction of each motor's speed limit (the robot file's), the fastest motor of a coupled sweep at it.</summary>
    public double SpeedFraction { get; init; } = 0.5;

    /// <summary>A motor further than this behind its setpoint (degrees of output) for <see cref="TrackingTime"/> stops the sweep: blocked.</summary>
    public double TrackingLimitDeg { get; init; } = 5;

    /// <summary>How long a motor may be beyond <see cref="TrackingLimitDeg"/>.</summary>
    public TimeSpan TrackingTime { get; init; } = TimeSpan.FromMilliseconds(500);

    /// <summary>A way point is reached within this many degrees of output.</summary>
    public double ArrivedDeg { get; init; } = 0.3;

    /// <summary>How long a sweep waits at a way point for the motors to get within <see cref="ArrivedDeg"/>.</summary>
    public TimeSpan SettleTime { get; init; } = TimeSpan.FromSeconds(1);

    /// <summary>
    /// A move (one leg of a sweep) must get through within this many times its length, plus <see cref="SettleTime"/>;
    /// bus holds (a late host: each holds the motors for a moment) that keep it longer stop the calibration.
    /// </summary>
    public double LegPatience { get; init; } = 3;

    /// <summary>Times the bus watchdog's second stage may turn a module's motors off (a stalled host) in one calibration before it stops: each is said, acknowledged and the motors armed again.</summary>
    public int MaxWatchdogStops { get; init; } = 5;

    /// <summary>Consecutive samples the verification averages (the pot's noise is not a disagreement).</summary>
    public int VerifyWindow { get; init; } = 5;

    /// <summary>
    /// The worst pot/encoder disagreement (degrees of output) the verification sweep accepts. It adds up: the fit's own
    /// error (up to a third of a degree on the LB-1.0's spacing, tests/RobotControl.Modules.Tests/PotCalibrationFitTests.cs),
    /// the gearhead's backlash between the encoder (on the motor) and the output the pot reads (up to its whole gap,
    /// 0.5 degrees at the LB-1.0 shoulders' outputs and 0.7 at the elbows', where the motion reverses), a count of pot noise and
    /// quantisation (0.14 degrees at the shoulder roll) and the age of the pot sample while moving.
    /// </summary>
    public double VerifyBoundDeg { get; init; } = 1.5;
}
