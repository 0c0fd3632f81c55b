namespace RobotControl.Robot.Bus;

/// <summary>
/// A robot's bus cycle as separate steps, for a schedule that runs the control loop in between (the virtual
/// schedule); a bus thread runs them back to back (<see cref="BusRobot.RunCycle"/>).
/// </summary>
public interface IBusCycle
{
    /// <summary>Step <b>write</b>: the latest setpoints become goals, sent to every module.</summary>
    void Write();

    /// <summary>Step <b>read</b>: every module's feedback is received (not yet published).</summary>
    void Read();

    /// <summary>Step <b>update</b>: the feedback read is published to the control loop's side and the modules are supervised.</summary>
    void Update();
}
