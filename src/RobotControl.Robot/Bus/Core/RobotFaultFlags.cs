using RobotControl.Robot.Control;

namespace RobotControl.Robot.Bus;

/// <summary>
/// The robot's fault flags as the bus thread finds them: latched ones (until faults are cleared) and live ones
/// (while the condition lasts). Any thread reads <see cref="Value"/>; a rejected setpoint is counted by the loop
/// side (<see cref="SetpointExchange.Rejected"/>) and shows here until faults are cleared.
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class RobotFaultFlags(SetpointExchange setpoints)
{
    private int _latched;
    private int _live;
    private long _rejectedCleared;

    public RobotFaults Value
    {
        get
        {
            var flags = (RobotFaults)(Volatile.Read(ref _latched) | Volatile.Read(ref _live));
            return setpoints.Rejected > Interlocked.Read(ref _rejectedCleared) ? flags | RobotFaults.SetpointRejected : flags;
        }
    }

    public bool IsLatched(RobotFaults fault) => (Volatile.Read(ref _latched) & (int)fault) != 0;

    public void Latch(RobotFaults fault) => Volatile.Write(ref _latched, _latched | (int)fault);

    public void SetLive(RobotFaults fault, bool on) => Volatile.Write(ref _live, on ? _live | (int)fault : _live & ~(int)fault);

    /// <summary>Clears the latched flags, and the setpoint rejections counted so far.</summary>
    public void ClearLatched()
    {
        Volatile.Write(ref _latched, 0);
        Interlocked.Exchange(ref _rejectedCleared, setpoints.Rejected);
    }
}
