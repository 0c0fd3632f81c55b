namespace RobotControl.Robot.Bus;

/// <summary>How old the input device data driving each arm is, as the graph reports it (the master timeout's input).</summary>
public sealed partial class BusRobot
{
    private readonly double[] _inputAgeMs;

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
}
