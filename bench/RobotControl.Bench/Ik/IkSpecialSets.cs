using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Bench.Ik;

/// <summary>
/// The hard corners of the workspace, as reachable targets (joint vectors and their forward kinematics), so that a
/// bound measured on uniform targets is not a bound only for easy ones:
/// <list type="bullet">
/// <item><c>near_singular</c>: a third with the elbow within 1° of its lower limit (stretched: the roll axes line up),
/// a third within 1° of its upper limit (folded), a third with two joint axes within 1° of parallel;</item>
/// <item><c>at_limits</c>: every joint at its lower limit, its upper limit or free, one in four each way, at least one at a limit;</item>
/// <item><c>near_boundary</c>: within 1 mm of the outer surface of the workspace.</item>
/// </list>
/// The elbow is the joint the robot file names <c>elbow</c>; without one, the first third draws from the aligned axes too.
/// </summary>
internal static class IkSpecialSets
{
    private const double Degree = Math.PI / 180;

    /// <summary>How many draws a near-singular target with aligned axes may take before the set gives up on it.</summary>
    private const int AlignedDrawLimit = 100_000;

    public static IkTargetSet NearSingular(KinematicChain chain, int count, ulong seed, OrientationAxes axes)
    {
        var random = new BenchRandom(seed ^ 0x51C6);
        var elbow = ElbowJoint(chain);
        var state = chain.CreateState();
        var joints = new double[count][];
        for (var s = 0; s < count; s++)
        {
            var kind = s % 3;
            if (elbow >= 0 && kind < 2)
            {
                var q = IkTargetSet.Uniform(chain, random);
                var offset = random.NextDouble() * Degree;
                q[elbow] = kind == 0
                    ? chain.MinRad[elbow] + offset
                    : chain.MaxRad[elbow] - offset;
                joints[s] = q;
            }
            else
            {
                joints[s] = AlignedAxes(chain, state, random);
            }
        }

        return IkTargetSet.FromJoints("near_singular", chain, joints, axes);
    }

    public static IkTargetSet AtLimits(KinematicChain chain, int count, ulong seed, OrientationAxes axes)
    {
        var random = new BenchRandom(seed ^ 0x1A17);
        var n = chain.JointCount;
        var joints = new double[count][];
        for (var s = 0; s < count; s++)
        {
            var q = IkTargetSet.Uniform(chain, random);
            var atLimit = 0;
            for (var i = 0; i < n; i++)
            {
                var u = random.NextDouble();
                if (u < 0.25)
                {
                    q[i] = chain.MinRad[i];
                    atLimit++;
                }
                else if (u < 0.5)
                {
                    q[i] = chain.MaxRad[i];
                    atLimit++;
                }
            }

            if (atLimit == 0)
            {
                var i = (int)(random.NextDouble() * n);
                q[i] = random.NextDouble() < 0.5 ? chain.MinRad[i] : chain.MaxRad[i];
            }

            joints[s] = q;
        }

        return IkTargetSet.FromJoints("at_limits", chain, joints, axes);
    }

    /// <summary>
    /// From a uniform start, gradient ascent of |p|² within the limits to a local maximum of the distance from the base
    /// (no neighbouring pose reaches further out, so the tool is on the workspace's outer surface there), then back
    /// towards the start until the tool is a uniform 0–1 mm further in.
    /// </summary>
    public static IkTargetSet NearBoundary(KinematicChain chain, int count, ulong seed, OrientationAxes axes)
    {
        var random = new BenchRandom(seed ^ 0xB0DA);
        var state = chain.CreateState();
        var n = chain.JointCount;
        var jacobian = new double[6 * n];
        var joints = new double[count][];
        var outer = new double[n];
        var trial = new double[n];
        for (var s = 0; s < count; s++)
        {
            var start = IkTargetSet.Uniform(chain, random);
            start.CopyTo(outer, 0);
            var reach = Ascend(chain, state, jacobian, outer, trial);
            var inward = random.NextDouble();

            // |p| along the joint-space segment from the outermost pose back to the start: bisect for reach - inward.
            state.Update(start);
            var lo = 0.0;
            var hi = 1.0;
            var q = new double[n];
            if (reach - state.ToolPosition.Length <= inward)
            {
                joints[s] = start;
                continue;
            }

            for (var k = 0; k < 60; k++)
            {
                var mid = 0.5 * (lo + hi);
                Lerp(outer, start, mid, q);
                state.Update(q);
                if (reach - state.ToolPosition.Length < inward)
                {
                    lo = mid;
                }
                else
                {
                    hi = mid;
                }
            }

            Lerp(outer, start, lo, q);
            joints[s] = q;
        }

        return IkTargetSet.FromJoints("near_boundary", chain, joints, axes);
    }

    private static int ElbowJoint(KinematicChain chain)
    {
        for (var i = 0; i < chain.JointCount; i++)
        {
            if (string.Equals(chain.Joints[i].Name, "elbow", StringComparison.Ordinal))
            {
                return i;
            }
        }

        return -1;
    }

    /// <summary>A uniform joint vector in which some two joint axes are within 1° of parallel (or anti-parallel).</summary>
    private static double[] AlignedAxes(KinematicChain chain, ChainState state, BenchRandom random)
    {
        var limit = Math.Sin(Degree);
        for (var draw = 0; draw < AlignedDrawLimit; draw++)
        {
            var q = IkTargetSet.Uniform(chain, random);
            state.Update(q);
            for (var i = 0; i < chain.JointCount; i++)
            {
                for (var j = i + 1; j < chain.JointCount; j++)
                {
                    if (Vector3d.Cross(state.JointAxis(i), state.JointAxis(j)).Length < limit)
                    {
                        return q;
                    }
                }
            }
        }

        throw new InvalidOperationException($"{chain.Name}: no pose with two joint axes within 1° of parallel in {AlignedDrawLimit} draws");
    }

    /// <summary>Projected gradient ascent of |p|² (step halved until it gains); returns the reach at the end.</summary>
    private static double Ascend(KinematicChain chain, ChainState state, double[] jacobian, double[] q, double[] trial)
    {
        var n = chain.JointCount;
        state.Update(q);
        var reach = state.ToolPosition.Length;
        var step = 1e-4;
        for (var iteration = 0; iteration < 400 && step > 1e-12; iteration++)
        {
            state.Jacobian(jacobian);
            var p = state.ToolPosition;
            for (var i = 0; i < n; i++)
            {
                var gradient = (p.X * jacobian[i]) + (p.Y * jacobian[n + i]) + (p.Z * jacobian[(2 * n) + i]);
                trial[i] = Math.Clamp(q[i] + (step * gradient), chain.MinRad[i], chain.MaxRad[i]);
            }

            state.Update(trial);
            var further = state.ToolPosition.Length;
            if (further > reach)
            {
                trial.CopyTo(q, 0);
                reach = further;
                step *= 1.5;
            }
            else
            {
                step *= 0.5;
                state.Update(q);
            }
        }

        return reach;
    }

    private static void Lerp(double[] from, double[] to, double t, double[] q)
    {
        for (var i = 0; i < q.Length; i++)
        {
            q[i] = from[i] + (t * (to[i] - from[i]));
        }
    }
}
