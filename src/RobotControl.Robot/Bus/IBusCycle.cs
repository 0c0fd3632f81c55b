namespace RobotControl.Robot.Bus;

/// <summary>
/// A robot's bus cycle as its steps, in order: <see cref="Write"/>, <see cref="Read"/>, <see cref="Publish"/>,
/// <see cref="Check"/>, then one piece of the work between cycles (<see cref="RunBetweenCycles"/>). A bus thread runs
/// them back to back (<see cref="BusRobot.RunCycle"/>); the virtual schedule runs the control loop's ticks in between.
/// Whoever runs the steps owns the bus while it does (<see cref="OwnBus"/>).
/// </summary>
public interface IBusCycle
{
    /// <summary>Step <b>write</b>: the checks of time alone (<see cref="ICycleCheck.BeforeWrite"/>), requests (a stop, a hold, faults cleared), then the latest setpoints become goals, sent to every module.</summary>
    void Write();

    /// <summary>Step <b>read</b>: every module's feedback is received (not yet published).</summary>
    void Read();

    /// <summary>Step <b>publish</b>: the feedback read is published to the control loop's side, and the modules are watched (status, pots, resets).</summary>
    void Publish();

    /// <summary>Step <b>check</b>: the safety supervisor's checks (<see cref="ICycleCheck"/>); what they decide reaches the wire at the next write.</summary>
    void Check();

    /// <summary>Between two cycles: the next piece of queued work (<see cref="BetweenCycles"/>), if any.</summary>
    void RunBetweenCycles();

    /// <summary>Makes the calling thread the bus's owner until the result is disposed.</summary>
    IDisposable OwnBus();
}

/// <summary>The per-cycle check of a safety supervisor: no bus traffic, no blocking, no allocation while nothing trips.</summary>
public interface ICycleCheck
{
    /// <summary>
    /// Runs the checks of time alone (how long since the last cycle: a host stall) just before the write, so that a
    /// hold decided here is taken by this very write rather than the next (bus thread).
    /// </summary>
    void BeforeWrite();

    /// <summary>Runs the checks on the cycle's fresh feedback (bus thread).</summary>
    void Check();
}
