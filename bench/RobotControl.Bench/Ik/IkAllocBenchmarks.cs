using BenchmarkDotNet.Attributes;
using RobotControl.Definitions.Loading;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Bench.Ik;

/// <summary>
/// BenchmarkDotNet view of one solve, for the memory diagnoser's allocated-bytes column (and a second opinion on time).
/// Run in-process by <see cref="IkAllocCommand"/>; the robot file comes from <see cref="RobotFile"/>.
/// </summary>
[MemoryDiagnoser]
public class IkAllocBenchmarks
{
    private IkSolver _solver = null!;
    private IkTargetSet _random = null!;
    private IkTargetSet _trajectory = null!;
    private double[] _seed = null!;
    private double[] _q = null!;
    private double[] _tracking = null!;
    private int _next;
    private int _step;

    /// <summary>Robot file to benchmark (set by the command before the run; in-process toolchain).</summary>
    public static string RobotFile { get; set; } = "hardware/robots/lb-1.0.json";

    [GlobalSetup]
    public void Setup()
    {
        var chain = new KinematicChain(RobotLoader.Load(RobotFile));
        var axes = chain.JointCount >= 5 ? OrientationAxes.All : OrientationAxes.Z;
        _solver = new IkSolver(chain);
        _random = IkTargetSet.Random(chain, 1024, 1, axes);
        _trajectory = IkTargetSet.Trajectory(chain, 20_000, 1, axes, 1.0);
        _seed = new double[chain.JointCount];
        chain.MidRange(_seed);
        _q = new double[chain.JointCount];
        _tracking = (double[])_trajectory.Joints[0].Clone();
    }

    /// <summary>One random reachable target from the mid-range seed (targets cycle through 1,024).</summary>
    [Benchmark]
    public IkStatus SolveFromMidRange()
    {
        var target = _random.Targets[_next];
        _next = (_next + 1) & 1023;
        return _solver.Solve(target, _seed, _q).Status;
    }

    /// <summary>The next 1 kHz trajectory point, seeded with the previous answer.</summary>
    [Benchmark]
    public IkStatus SolveTracking()
    {
        var target = _trajectory.Targets[_step];
        if (++_step == _trajectory.Targets.Length)
        {
            _step = 0;
            _trajectory.Joints[0].CopyTo(_tracking, 0);
        }

        return _solver.Solve(target, _tracking, _tracking).Status;
    }
}
