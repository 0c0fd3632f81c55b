namespace RobotControl.Robot.Bus;

/// <summary>
/// What the graph reports about the operator's input devices, for a safety supervisor: how old the data driving each
/// arm is (the master timeout) and the pedals (teleoperation, emergency stop).
/// </summary>
public sealed partial class BusRobot
{
    private readonly double[] _inputAgeMs;
    private volatile int _pedal;
    private volatile int _emergencyStop;

    /// <inheritdoc cref="RobotControl.Robot.Control.IRobotPort.ReportInputAge"/>
    public void ReportInputAge(int arm, double ageMs)
    {
        if ((uint)arm < (uint)ArmCount)
        {
            Volatile.Write(ref _inputAgeMs[arm], double.IsNaN(ageMs) ? double.PositiveInfinity : ageMs);
        }
    }

    /// <summary>The age last reported for <paramref name="arm"/>'s input device data, ms (0 before any report: no device, never stale).</summary>
    public double InputAgeMs(int arm) => (uint)arm < (uint)ArmCount ? Volatile.Read(ref _inputAgeMs[arm]) : 0;

    /// <inheritdoc cref="RobotControl.Robot.Control.IRobotPort.ReportPedal"/>
    public void ReportPedal(bool down) => _pedal = down ? (int)OperatorPedal.Down : (int)OperatorPedal.Up;

    /// <inheritdoc cref="RobotControl.Robot.Control.IRobotPort.ReportEmergencyStop"/>
    public void ReportEmergencyStop(bool pressed) => _emergencyStop = pressed ? (int)OperatorPedal.Down : (int)OperatorPedal.Up;

    /// <summary>The teleoperation pedal as last reported (<see cref="OperatorPedal.None"/>: the graph has none).</summary>
    public OperatorPedal Pedal => (OperatorPedal)_pedal;

    /// <summary>The emergency-stop pedal or button as last reported (<see cref="OperatorPedal.None"/>: the graph has none; down: pressed).</summary>
    public OperatorPedal EmergencyStopPedal => (OperatorPedal)_emergencyStop;
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
