namespace RobotControl.Robot.Bus;

/// <summary>The threads of a robot on its bus, as the robot core's types name them.</summary>
public enum RobotThread
{
    /// <summary>The control loop's thread (the graph's ticks): it alone writes the setpoints.</summary>
    Loop,

    /// <summary>
    /// The thread that owns the bus: the bus thread of a wall-clock session, or the thread running a virtual schedule
    /// or <see cref="BusRobot.RunFor"/>. It runs the cycle and the work between cycles (<see cref="BetweenCycles"/>).
    /// </summary>
    Bus,

    /// <summary>Nobody: the type holds nothing that changes after it is built.</summary>
    None,
}

/// <summary>
/// Says which thread writes the mutable state of a part of the robot core. Other threads only read it (through
/// <see cref="Definitions.Exchange.SeqLock{T}"/>, volatile or interlocked reads) or ask for a change through a request
/// that the writing thread takes up (members named <c>Request…</c>, <c>Hold…</c> or <c>Raise…</c>).
/// </summary>
[AttributeUsage(AttributeTargets.Class, Inherited = false)]
public sealed class WrittenByAttribute(RobotThread thread) : Attribute
{
    /// <summary>The writing thread.</summary>
    public RobotThread Thread { get; } = thread;
}
