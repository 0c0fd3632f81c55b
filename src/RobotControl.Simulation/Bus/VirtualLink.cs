using RobotControl.Bus.Transports;

namespace RobotControl.Simulation.Bus;

/// <summary>
/// The host's end of a virtual bus: a read that finds nothing runs the simulation forward on its clock until bytes
/// arrive or the timeout has passed in simulated time.
/// </summary>
internal sealed class VirtualLink(VirtualRobot robot) : IByteLink, IClockedLink
{
    public string Description => $"virtual bus of {robot.Definition.Name} at {BaudRate} baud";

    public int BaudRate => robot.BaudRate;

    public TimeProvider Clock => robot.Clock;

    public void Write(ReadOnlySpan<byte> data) => robot.HostWrite(data);

    public int Read(Span<byte> buffer, TimeSpan timeout) => robot.HostRead(buffer, timeout);

    public void DiscardInput() => robot.HostDiscard();

    public void Dispose()
    {
        // The virtual robot owns the bus; closing the host end leaves it running.
    }
}
