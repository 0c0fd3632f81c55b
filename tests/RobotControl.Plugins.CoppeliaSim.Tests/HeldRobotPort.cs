using RobotControl.Definitions.Model;
using RobotControl.Robot.Control;

namespace RobotControl.Plugins.CoppeliaSim.Tests;

/// <summary>A robot port that keeps the setpoints it is given and reports them as positions (no bus).</summary>
internal sealed class HeldRobotPort(RobotDefinition robot) : IRobotPort
{
    private readonly double[][] _joints = [.. robot.Arms.Select(_ => new double[robot.JointCount])];

    public RobotDefinition Definition => robot;

    public int ArmCount => robot.Arms.Count;

    public RobotFaults Faults => RobotFaults.None;

    public void WriteJointSetpoints(int arm, ReadOnlySpan<double> jointsRad) => jointsRad.CopyTo(_joints[arm]);

    public void WriteJawSetpoint(int arm, double jawRad)
    {
    }

    public void ReadJointPositions(int arm, Span<double> jointsRad) => _joints[arm].CopyTo(jointsRad);

    public void ReadMotorCurrents(int arm, Span<double> currentsA) => currentsA.Clear();

    public void HoldPosition()
    {
    }
}
