using RobotControl.Definitions.Model;
using RobotControl.Robot.Control;

namespace RobotControl.TestSupport;

/// <summary>Test double: an ideal robot whose joints are wherever they were last commanded while teleoperation is allowed (else it holds), and an operator port whose run level the test sets.</summary>
public sealed class KinematicRobotPort(RobotDefinition robot) : IRobotPort, IOperatorPort
{
    private readonly double[][] _joints = [.. robot.Arms.Select(_ => robot.Joints.Select(j => j.MidRad).ToArray())];

    public RobotDefinition Definition { get; } = robot;

    public int ArmCount => Definition.Arms.Count;

    public RobotFaults Faults { get; private set; }

    public int Writes { get; private set; }

    public int Holds { get; private set; }

    public void WriteJointSetpoints(int arm, ReadOnlySpan<double> jointsRad)
    {
        foreach (var v in jointsRad)
        {
            if (!double.IsFinite(v))
            {
                Faults |= RobotFaults.SetpointRejected;
                return;
            }
        }

        Writes++;
        if (TeleopAllowed)
        {
            jointsRad.CopyTo(_joints[arm]); // else the arm holds, as under the supervisor's hold at PEDAL_UP
        }
    }

    public void WriteJawSetpoint(int arm, double jawRad)
    {
    }

    public void ReadJointPositions(int arm, Span<double> jointsRad) => _joints[arm].CopyTo(jointsRad);

    /// <summary>Puts <paramref name="arm"/>'s joints at <paramref name="jointsRad"/> (the arm moved by other means, e.g. by hand).</summary>
    public void MoveTo(int arm, ReadOnlySpan<double> jointsRad) => jointsRad.CopyTo(_joints[arm]);

    public void ReadMotorCurrents(int arm, Span<double> currentsA) => currentsA.Clear();

    public void HoldPosition() => Holds++;

    /// <summary>What <see cref="IOperatorPort.TeleopAllowed"/> answers (a supervisor's run level).</summary>
    public bool TeleopAllowed { get; set; } = true;

    /// <summary>The speed limit <see cref="ReportInputSpeed"/> answers against (a supervisor's <c>master_speed_max_mm_s</c>).</summary>
    public double SpeedLimitMmPerS { get; set; } = double.PositiveInfinity;

    /// <summary>Ticks reported.</summary>
    public int Ticks { get; private set; }

    public void ReportTick() => Ticks++;

    public void ReportInputAge(int arm, double ageMs)
    {
    }

    public bool ReportInputSpeed(int arm, double mmPerS) => mmPerS <= SpeedLimitMmPerS;

    public void ReportPedal(bool down)
    {
    }

    public void ReportEmergencyStop(bool pressed)
    {
    }
}
