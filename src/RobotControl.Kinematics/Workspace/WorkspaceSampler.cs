using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Inverse;
using RobotControl.Kinematics.Mirroring;

namespace RobotControl.Kinematics.Workspace;

/// <summary>
/// The reachable workspace of each arm of a robot file, sampled by forward kinematics over the joint limits: tool-tip
/// positions in the body frame (the frame of <see cref="Urdf.UrdfExport"/>'s <c>body</c> link, mm), arms placed and
/// mirrored as the file says. <see cref="ArmWorkspace.Interior"/> draws every joint uniformly within its limits;
/// <see cref="ArmWorkspace.Walls"/> pins one position joint at a limit (the surfaces where a joint limit stops the tool:
/// the workspace's walls, plus limit surfaces that fold inside it). Joints that do not move the tip (a tool roll) are
/// never pinned. Deterministic for a seed.
/// </summary>
public static class WorkspaceSampler
{
    /// <summary>Samples every arm of <paramref name="robot"/>: <paramref name="interior"/> and <paramref name="walls"/> points per arm.</summary>
    /// <exception cref="ArgumentOutOfRangeException">A count is negative or above 100 000.</exception>
    public static IReadOnlyList<ArmWorkspace> Sample(RobotDefinition robot, int interior, int walls, ulong seed = 1)
    {
        ArgumentNullException.ThrowIfNull(robot);
        ArgumentOutOfRangeException.ThrowIfNegative(interior);
        ArgumentOutOfRangeException.ThrowIfNegative(walls);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(interior, 100_000);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(walls, 100_000);
        var chain = new KinematicChain(robot);
        var state = chain.CreateState();
        var pinnable = PositionJoints(chain, state);
        var result = new List<ArmWorkspace>(robot.Arms.Count);
        foreach (var arm in robot.Arms)
        {
            // The same draws for every arm: the mirrored arm's cloud is the mirror image of the other's.
            var random = new XorShiftRandom(seed);
            var mirror = new ArmMirror(robot, arm.Name);
            var q = new double[chain.JointCount];
            var inside = new Vector3d[interior];
            for (var i = 0; i < interior; i++)
            {
                Draw(chain, ref random, q);
                state.Update(q);
                inside[i] = mirror.ModelToBody(state.ToolPosition);
            }

            var wall = new Vector3d[pinnable.Count == 0 ? 0 : walls];
            for (var i = 0; i < wall.Length; i++)
            {
                Draw(chain, ref random, q);
                var face = i % (2 * pinnable.Count);
                var joint = pinnable[face / 2];
                q[joint] = face % 2 == 0 ? chain.MinRad[joint] : chain.MaxRad[joint];
                state.Update(q);
                wall[i] = mirror.ModelToBody(state.ToolPosition);
            }

            result.Add(new ArmWorkspace(arm.Name, inside, wall));
        }

        return result;
    }

    private static void Draw(KinematicChain chain, ref XorShiftRandom random, double[] q)
    {
        for (var j = 0; j < q.Length; j++)
        {
            q[j] = chain.MinRad[j] + (random.NextDouble() * (chain.MaxRad[j] - chain.MinRad[j]));
        }
    }

    /// <summary>The joints whose value moves the tool tip (tried at a few poses: mid-range and near each end).</summary>
    private static List<int> PositionJoints(KinematicChain chain, ChainState state)
    {
        var joints = new List<int>();
        var q = new double[chain.JointCount];
        for (var j = 0; j < chain.JointCount; j++)
        {
            foreach (var at in (ReadOnlySpan<double>)[0.5, 0.2, 0.8])
            {
                for (var k = 0; k < q.Length; k++)
                {
                    q[k] = chain.MinRad[k] + (at * (chain.MaxRad[k] - chain.MinRad[k]));
                }

                q[j] = chain.MinRad[j];
                state.Update(q);
                var low = state.ToolPosition;
                q[j] = chain.MaxRad[j];
                state.Update(q);
                if ((state.ToolPosition - low).Length > 1e-6)
                {
                    joints.Add(j);
                    break;
                }
            }
        }

        return joints;
    }
}

/// <summary>One arm's sampled workspace (body frame, mm).</summary>
/// <param name="Arm">Arm name.</param>
/// <param name="Interior">Tool-tip positions with every joint drawn within its limits.</param>
/// <param name="Walls">Tool-tip positions with one position joint at a limit.</param>
public sealed record ArmWorkspace(string Arm, IReadOnlyList<Vector3d> Interior, IReadOnlyList<Vector3d> Walls);
