using RobotControl.Analysis.Drivetrain;
using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Forward;

namespace RobotControl.Analysis.Sweep;

/// <summary>
/// Evaluates a <see cref="SweepSpecification"/> (docs/algorithms.md, capability analysis): at every grid
/// point the used joints' position Jacobian J (3 x m, mm/rad) gives the manipulability, the largest speed along each
/// axis v_a = Σ_i |J_a,i| omega_i and the largest holdable force along each axis (see <see cref="ForceSearch"/>).
/// </summary>
internal static class CapabilitySweep
{
    public static SweepResult Run(
        RobotDefinition robot,
        SweepSpecification spec,
        JointDriveLimits limits,
        CoupledDriveModel? coupled)
    {
        limits.RequireJoints(robot, spec.JointsUsed);
        if (spec.FixedRad.Count != robot.JointCount)
        {
            throw new ArgumentException($"the sweep gives {spec.FixedRad.Count} joint values; {robot.Name} has {robot.JointCount} joints");
        }

        var chain = new KinematicChain(robot);
        var result = new SweepResult(spec, robot.JointCount, coupled is not null);
        var used = spec.JointsUsed;
        var m = used.Count;
        var speed = used.Select(j => limits.SpeedRadPerS[j]).ToArray();
        var torque = used.Select(j => limits.TorqueMNm[j]).ToArray();

        Parallel.For(0, spec.XCount, ix =>
        {
            var state = chain.CreateState();
            var q = new double[robot.JointCount];
            var full = new double[6 * robot.JointCount];
            var j = new double[3 * m];
            var k = new double[3 * m];
            for (var iy = 0; iy < spec.YCount; iy++)
            {
                var index = (ix * spec.YCount) + iy;
                result.JointsAt(index, q);
                state.Update(q);
                state.Jacobian(full);
                PositionJacobian.Extract(full, robot.JointCount, used, j);
                var tool = state.ToolPosition;
                result.Position[0][index] = tool.X;
                result.Position[1][index] = tool.Y;
                result.Position[2][index] = tool.Z;
                result.Manipulability[index] = PositionJacobian.Manipulability(j, m);
                Evaluate(j, m, speed, torque, result.Reference, index);
                if (coupled is not null)
                {
                    coupled.MapJacobian(j, k);
                    Evaluate(k, m, coupled.SpeedRadPerS, coupled.TorqueMNm, result.CouplingAware!, index);
                }
            }
        });

        var max = result.Manipulability.Max();
        for (var i = 0; i < result.Count; i++)
        {
            result.ManipulabilityNormalised[i] = max > 0 ? result.Manipulability[i] / max : 0.0;
        }

        return result;
    }

    /// <summary>Velocity and force along X, Y, Z from the 3 x m matrix <paramref name="j"/> and per-column limits.</summary>
    internal static void Evaluate(ReadOnlySpan<double> j, int m, ReadOnlySpan<double> speed, ReadOnlySpan<double> torque, CapabilityMaps maps, int index)
    {
        for (var axis = 0; axis < 3; axis++)
        {
            var row = j.Slice(axis * m, m);
            var v = 0.0;
            for (var i = 0; i < m; i++)
            {
                v += Math.Abs(row[i]) * speed[i];
            }

            maps.Velocity[axis][index] = v;
            maps.Force[axis][index] = ForceSearch.Largest(row, torque);
        }
    }
}
