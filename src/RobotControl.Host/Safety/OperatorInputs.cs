using RobotControl.Robot.Bus;
using RobotControl.Robot.Control;

namespace RobotControl.Host.Safety;

/// <summary>
/// What the graph reports about the operator, as the loop's thread writes it every tick: how old the data driving
/// each arm is (the master timeout; NaN counts as too old, 0 before any report: no device, never stale), the
/// teleoperation pedal and the emergency-stop pedal or button. The supervisor's checks read it on the bus thread.
/// </summary>
[WrittenBy(RobotThread.Loop)]
internal sealed class OperatorInputs(int arms)
{
    private readonly double[] _ageMs = new double[arms];
    private volatile int _pedal;
    private volatile int _emergencyStop;

    public OperatorPedal Pedal => (OperatorPedal)_pedal;

    public OperatorPedal EmergencyStop => (OperatorPedal)_emergencyStop;

    public double AgeMs(int arm) => (uint)arm < (uint)_ageMs.Length ? Volatile.Read(ref _ageMs[arm]) : 0;

    public void ReportAge(int arm, double ageMs)
    {
        if ((uint)arm < (uint)_ageMs.Length)
        {
            Volatile.Write(ref _ageMs[arm], double.IsNaN(ageMs) ? double.PositiveInfinity : ageMs);
        }
    }

    public void ReportPedal(bool down) => _pedal = (int)(down ? OperatorPedal.Down : OperatorPedal.Up);

    public void ReportEmergencyStop(bool pressed) => _emergencyStop = (int)(pressed ? OperatorPedal.Down : OperatorPedal.Up);
}

/// <summary>An operator pedal or button as the graph reports it.</summary>
public enum OperatorPedal
{
    /// <summary>Never reported: the graph has none.</summary>
    None,

    /// <summary>Released.</summary>
    Up,

    /// <summary>Pressed.</summary>
    Down,
}
