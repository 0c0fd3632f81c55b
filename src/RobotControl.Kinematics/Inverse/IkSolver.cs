using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Inverse;

/// <summary>
/// Numerical inverse kinematics for any revolute DH chain (docs/algorithms.md): cyclic coordinate descent with the analytic
/// per-joint step to get near, then a bound-constrained damped Gauss-Newton (Levenberg-Marquardt) on the exact Jacobian
/// of position and selected axes ((3 + 3k) x n) with the joint limits inside the iteration. When a run stalls at a limit
/// or a local minimum it restarts: first by hops along the free direction of a singular pose
/// (<see cref="AlignedAxisHops"/>), then from the nearest unused seed of a fixed set spread over the joint box
/// (<see cref="RestartSeeds"/>); all deterministic. Warm starts: pass the previous solution as the seed. The work per
/// solve has a hard ceiling (<see cref="IkOptions.MaxIterations"/>); a solve that meets it returns the best pose found,
/// flagged (<see cref="IkResult.AtCeiling"/>). An unreachable or degenerate target gives the best reachable pose found
/// and a finite workspace force. One instance per thread; allocates only when
/// constructed. The output is joint angles; map them to motors (shoulder couplings) with
/// <see cref="Coupling.JointMotorMap"/>.
/// </summary>
public sealed class IkSolver
{
    // Tuned on LB-1.0 / CRB-1.0 with bench/RobotControl.Bench ik (docs/perf/ik.md).
    // CCD cycles before the Newton steps on the first start only: from the seed they cut the iteration count by a
    // fifth; from restart seeds they tended to fold the LB-1.0 elbow onto its 0 limit (a local minimum).
    private const int CcdCyclesFirstStart = 1;

    // A run that gains less than this fraction of its cost in an accepted step is at a local minimum: restart.
    private const double StallRatio = 1e-4;
    private const int StepsPerRun = 40;

    // Stalled poses searched for aligned axes per solve (each proposes up to AlignedAxisHops.MaxHops restarts).
    private const int MaxHopSearches = 2;

    // Unreachable: the best start is polished to its constrained minimum (the restart loop stops runs early).
    private const int PolishSteps = 30;
    private const double PolishStallRatio = 1e-13;

    private readonly IkProblem _problem;
    private readonly BoundedLevenbergMarquardt _descent;
    private readonly double[] _current;
    private readonly double[] _best;
    private readonly double[] _sampleMin;
    private readonly double[] _sampleMax;
    private readonly RestartSeeds _restartSeeds;
    private readonly AlignedAxisHops _hops;

    /// <summary>Creates a solver and all its workspace for <paramref name="chain"/>.</summary>
    /// <exception cref="ArgumentException">A joint range is empty or NaN, or an option is out of range.</exception>
    public IkSolver(KinematicChain chain, IkOptions? options = null)
    {
        ArgumentNullException.ThrowIfNull(chain);
        options ??= new IkOptions();
        Validate(options);
        Chain = chain;
        Options = options;
        var n = chain.JointCount;
        _sampleMin = new double[n];
        _sampleMax = new double[n];
        for (var i = 0; i < n; i++)
        {
            var min = chain.MinRad[i];
            var max = chain.MaxRad[i];
            if (!(min <= max))
            {
                throw new ArgumentException($"joint {i} has an empty or undefined range [{min}, {max}]", nameof(chain));
            }

            // Restart seeds need a finite interval; an unbounded side is one turn from the other (or ±π).
            _sampleMin[i] = double.IsFinite(min) ? min : double.IsFinite(max) ? max - (2 * Math.PI) : -Math.PI;
            _sampleMax[i] = double.IsFinite(max) ? max : _sampleMin[i] + (2 * Math.PI);
        }

        _problem = new IkProblem(chain, options);
        _descent = new BoundedLevenbergMarquardt(chain);
        _current = new double[n];
        _best = new double[n];
        _restartSeeds = new RestartSeeds(chain, _sampleMin, _sampleMax);
        _hops = new AlignedAxisHops(chain, _sampleMin, _sampleMax);
    }

    /// <summary>The chain solved for.</summary>
    public KinematicChain Chain { get; }

    /// <summary>The solver settings.</summary>
    public IkOptions Options { get; }

    /// <summary>
    /// Solves for <paramref name="target"/> from <paramref name="seed"/> (the previous solution when tracking; NaN or
    /// infinite entries are replaced by mid-range, out-of-range ones clamped) and writes the joint vector (radians,
    /// always within limits, never NaN) to <paramref name="solution"/>. Allocation-free; never throws once constructed
    /// except for spans shorter than the joint count.
    /// </summary>
    public IkResult Solve(in IkTarget target, ReadOnlySpan<double> seed, Span<double> solution)
    {
        var n = Chain.JointCount;
        if (seed.Length < n)
        {
            throw new ArgumentException($"seed has {seed.Length} values; the chain has {n} joints", nameof(seed));
        }

        if (solution.Length < n)
        {
            throw new ArgumentException($"solution has room for {solution.Length} values; the chain has {n} joints", nameof(solution));
        }

        var min = Chain.MinRad;
        var max = Chain.MaxRad;
        var current = _current.AsSpan();
        for (var i = 0; i < n; i++)
        {
            var value = seed[i];
            current[i] = double.IsFinite(value) ? Math.Clamp(value, min[i], max[i]) : 0.5 * (_sampleMin[i] + _sampleMax[i]);
        }

        var problem = _problem;
        if (!problem.SetTarget(target))
        {
            problem.Evaluate(current);
            current.CopyTo(solution);
            return new IkResult(IkStatus.InvalidTarget, problem.State.ToolPosition, double.PositiveInfinity,
                double.PositiveInfinity, Vector3d.Zero, 0);
        }

        var totalBudget = Math.Max(Options.MaxIterations, 1);
        var loopBudget = Math.Max(totalBudget - PolishSteps, (totalBudget + 1) / 2);
        var budget = loopBudget;
        var best = _best.AsSpan();
        var cost = problem.Evaluate(current);
        current.CopyTo(best);
        var bestCost = cost;
        var reached = false;
        var hopped = 0;
        var ranked = false;
        _hops.Clear();
        for (var restart = 0; ; restart++)
        {
            // A warm start that is already close goes straight to the Newton steps; CCD only helps from afar.
            if (restart == 0 && cost > WarmStartCost() && !problem.WithinTolerance())
            {
                for (var c = 0; c < CcdCyclesFirstStart && budget > 1; c++)
                {
                    cost = CyclicCoordinateDescent.Cycle(problem, current);
                    budget--;
                }
            }

            var outcome = _descent.Run(problem, current, ref cost, ref budget, StepsPerRun, StallRatio);

            // A run that used its steps while still converging (slowly, near a singularity) and is close goes on.
            while (outcome == BoundedLevenbergMarquardt.Outcome.OutOfBudget && budget > 0 && cost < WarmStartCost())
            {
                outcome = _descent.Run(problem, current, ref cost, ref budget, StepsPerRun, StallRatio);
            }

            if (outcome == BoundedLevenbergMarquardt.Outcome.Reached)
            {
                current.CopyTo(best);
                reached = true;
                break;
            }

            if (cost < bestCost)
            {
                bestCost = cost;
                current.CopyTo(best);
            }

            if (budget <= 0 || restart >= Options.MaxRestarts)
            {
                break;
            }

            // Stalled at a singular pose (often with a joint on its limit): hop along its free direction before trying
            // far seeds.
            if (!_hops.Any && hopped < MaxHopSearches)
            {
                hopped++;
                _hops.Propose(problem.State, current);
            }

            if (_hops.Any)
            {
                _hops.Next(current);
            }
            else
            {
                // Ranked once per solve, on the first seed taken (a solve the hops finish never pays for it).
                if (!ranked)
                {
                    _restartSeeds.Rank(problem);
                    ranked = true;
                }

                _restartSeeds.Next(current);
            }

            cost = problem.Evaluate(current);
        }

        var used = loopBudget - budget;
        if (!reached)
        {
            // The state holds the last start's frames; the best start may be another.
            bestCost = problem.Evaluate(best);
            var polish = totalBudget - used;
            var before = polish;
            reached = _descent.Run(problem, best, ref bestCost, ref polish, PolishSteps, PolishStallRatio)
                == BoundedLevenbergMarquardt.Outcome.Reached;
            used += before - polish;
        }

        best.CopyTo(solution);
        return Result(target, reached, used, !reached && used >= totalBudget);
    }

    /// <summary>E of docs/algorithms.md for <paramref name="q"/> (weights from <see cref="Options"/>); for tests and tools.</summary>
    internal double SpecError(in IkTarget target, ReadOnlySpan<double> q)
    {
        _problem.SetTarget(target);
        _problem.Evaluate(q);
        return _problem.SpecError();
    }

    /// <summary>dE/dθ of docs/algorithms.md for <paramref name="q"/>; for tests and tools.</summary>
    internal void SpecGradient(in IkTarget target, ReadOnlySpan<double> q, Span<double> gradient)
    {
        _problem.SetTarget(target);
        _problem.Evaluate(q);
        _problem.SpecGradient(gradient);
    }

    /// <summary>The problem workspace (for tests of the CCD step).</summary>
    internal IkProblem Problem => _problem;

    // The cost of being about 1 mm off (PositionWeight per mm²): Newton from here is faster than a CCD sweep.
    private double WarmStartCost() => _problem.PositionWeight;

    private IkResult Result(in IkTarget target, bool reached, int iterations, bool atCeiling)
    {
        var problem = _problem;
        var reachedPosition = problem.State.ToolPosition;
        var offset = reachedPosition - target.Position;
        var force = Vector3d.Zero;
        if (!reached)
        {
            var k = Options.WorkspaceStiffnessNPerMm;
            force = new Vector3d(Finite(k * offset.X), Finite(k * offset.Y), Finite(k * offset.Z));
        }

        var positionError = IkProblem.SafeLength(offset);
        return new IkResult(
            reached ? IkStatus.Reached : IkStatus.Unreachable,
            reachedPosition,
            double.IsFinite(positionError) ? positionError : double.MaxValue,
            problem.LargestAxisAngle(),
            force,
            iterations,
            atCeiling);
    }

    private static double Finite(double value) =>
        double.IsNaN(value) ? 0 : Math.Clamp(value, -double.MaxValue, double.MaxValue);

    private static void Validate(IkOptions options)
    {
        static void Positive(double value, string name)
        {
            if (!(value > 0) || !double.IsFinite(value))
            {
                throw new ArgumentOutOfRangeException(nameof(options), value, $"{name} must be positive and finite");
            }
        }

        Positive(options.PositionToleranceMm, nameof(options.PositionToleranceMm));
        Positive(options.OrientationToleranceRad, nameof(options.OrientationToleranceRad));
        Positive(options.PositionWeight, nameof(options.PositionWeight));
        Positive(options.OrientationWeight, nameof(options.OrientationWeight));
        if (!(options.WorkspaceStiffnessNPerMm >= 0) || !double.IsFinite(options.WorkspaceStiffnessNPerMm))
        {
            throw new ArgumentOutOfRangeException(nameof(options), options.WorkspaceStiffnessNPerMm, "WorkspaceStiffnessNPerMm must be finite and not negative");
        }

        if (options.MaxIterations < 1 || options.MaxRestarts < 0)
        {
            throw new ArgumentOutOfRangeException(nameof(options), "MaxIterations must be at least 1 and MaxRestarts not negative");
        }
    }
}
