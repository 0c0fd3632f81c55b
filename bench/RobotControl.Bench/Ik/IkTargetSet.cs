using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Bench.Ik;

/// <summary>
/// Benchmark targets: joint vectors drawn uniformly within the joint ranges (deterministic xorshift from the seed) and
/// their tool pose by forward kinematics, so every target is reachable.
/// </summary>
internal sealed class IkTargetSet
{
    private IkTargetSet(string name, KinematicChain chain, IkTarget[] targets, double[][] joints)
    {
        Name = name;
        Chain = chain;
        Targets = targets;
        Joints = joints;
    }

    /// <summary>What the set is (random, near_singular, at_limits, near_boundary, tracking), as the JSON names it.</summary>
    public string Name { get; }

    public KinematicChain Chain { get; }

    public IkTarget[] Targets { get; }

    /// <summary>The joint vectors the targets were made from (one exact answer each).</summary>
    public double[][] Joints { get; }

    public static IkTargetSet Random(KinematicChain chain, int count, ulong seed, OrientationAxes axes)
    {
        var random = new BenchRandom(seed);
        var n = chain.JointCount;
        var joints = new double[count][];
        for (var s = 0; s < count; s++)
        {
            joints[s] = Uniform(chain, random);
        }

        return FromJoints("random", chain, joints, axes);
    }

    /// <summary>The targets that <paramref name="joints"/> reach, by forward kinematics.</summary>
    public static IkTargetSet FromJoints(string name, KinematicChain chain, double[][] joints, OrientationAxes axes)
    {
        var state = chain.CreateState();
        var targets = new IkTarget[joints.Length];
        for (var s = 0; s < joints.Length; s++)
        {
            state.Update(joints[s]);
            targets[s] = new IkTarget(state.ToolPosition, state.ToolRotation, axes);
        }

        return new IkTargetSet(name, chain, targets, joints);
    }

    /// <summary>A joint vector uniform within the joint ranges.</summary>
    public static double[] Uniform(KinematicChain chain, BenchRandom random)
    {
        var q = new double[chain.JointCount];
        for (var i = 0; i < q.Length; i++)
        {
            q[i] = chain.MinRad[i] + (random.NextDouble() * (chain.MaxRad[i] - chain.MinRad[i]));
        }

        return q;
    }

    /// <summary>
    /// A smooth random tool trajectory sampled at 1 kHz: a sum of slow sinusoids per joint inside the joint ranges,
    /// mapped by forward kinematics, with the time step shrunk until no tool step exceeds <paramref name="maxStepMm"/>.
    /// </summary>
    public static IkTargetSet Trajectory(KinematicChain chain, int count, ulong seed, OrientationAxes axes, double maxStepMm)
    {
        var n = chain.JointCount;
        var random = new BenchRandom(seed ^ 0xABCDEF);
        var amplitude = new double[n, 3];
        var frequency = new double[n, 3];
        var phase = new double[n, 3];
        for (var i = 0; i < n; i++)
        {
            for (var h = 0; h < 3; h++)
            {
                amplitude[i, h] = random.NextDouble() / 3.0;
                frequency[i, h] = 0.05 + (0.25 * random.NextDouble());
                phase[i, h] = 2 * Math.PI * random.NextDouble();
            }
        }

        var state = chain.CreateState();
        var dt = 1e-3;
        while (true)
        {
            var targets = new IkTarget[count];
            var joints = new double[count][];
            var previous = Vector3d.Zero;
            var largest = 0.0;
            for (var s = 0; s < count; s++)
            {
                var t = s * dt;
                var q = new double[n];
                for (var i = 0; i < n; i++)
                {
                    var u = 0.0;
                    for (var h = 0; h < 3; h++)
                    {
                        u += amplitude[i, h] * Math.Sin((2 * Math.PI * frequency[i, h] * t) + phase[i, h]);
                    }

                    // u in (-1, 1): map into the middle 90 % of the range.
                    var mid = 0.5 * (chain.MinRad[i] + chain.MaxRad[i]);
                    var half = 0.45 * (chain.MaxRad[i] - chain.MinRad[i]);
                    q[i] = mid + (half * u);
                }

                state.Update(q);
                targets[s] = new IkTarget(state.ToolPosition, state.ToolRotation, axes);
                joints[s] = q;
                if (s > 0)
                {
                    largest = Math.Max(largest, Vector3d.Distance(previous, state.ToolPosition));
                }

                previous = state.ToolPosition;
            }

            if (largest <= maxStepMm)
            {
                return new IkTargetSet("tracking", chain, targets, joints);
            }

            dt *= 0.8 * maxStepMm / largest;
        }
    }
}
