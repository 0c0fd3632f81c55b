using RobotControl.Kinematics.Forward;

namespace RobotControl.Kinematics.Inverse;

/// <summary>
/// Damped Gauss-Newton (Levenberg-Marquardt) on the least-squares form of <see cref="IkProblem"/> with the joint limits
/// inside the iteration: a projected Newton step (Bertsekas) that freezes joints sitting on a bound whose gradient
/// points outward, solves the damped normal equations for the rest and projects the step onto the box. Written here
/// because ALGLIB (minlbfgs/minlm) is not served; allocates only in the constructor.
/// </summary>
internal sealed class BoundedLevenbergMarquardt
{
    private const double InitialDamping = 1e-3;
    private const double MinDamping = 1e-12;
    private const double MaxDamping = 1e8;
    private const double MaxStepRad = 1.0;
    private const double BoundSlackRad = 1e-12;

    private readonly int _n;
    private readonly double[] _jacobian;
    private readonly double[] _normal;
    private readonly double[] _jtr;
    private readonly double[] _system;
    private readonly double[] _step;
    private readonly double[] _trial;
    private readonly int[] _free;
    private readonly KinematicChain _chain;

    internal BoundedLevenbergMarquardt(KinematicChain chain)
    {
        var jointCount = chain.JointCount;
        _n = jointCount;
        _chain = chain;
        _jacobian = new double[12 * jointCount];
        _normal = new double[jointCount * jointCount];
        _jtr = new double[jointCount];
        _system = new double[jointCount * jointCount];
        _step = new double[jointCount];
        _trial = new double[jointCount];
        _free = new int[jointCount];
    }

    /// <summary>Why a run ended.</summary>
    internal enum Outcome
    {
        /// <summary>Within tolerance.</summary>
        Reached,

        /// <summary>At a (bound-constrained) stationary point or making no progress: a local minimum or unreachable.</summary>
        Stalled,

        /// <summary>The iteration budget ran out.</summary>
        OutOfBudget,
    }

    /// <summary>
    /// Minimises from <paramref name="q"/> (within limits; the problem's state must hold its frames and
    /// <paramref name="cost"/> its cost). On return q, cost and the state describe the best point found. Each trial
    /// step costs one unit of <paramref name="budget"/>; at most <paramref name="maxSteps"/> are spent in this run.
    /// </summary>
    internal Outcome Run(IkProblem problem, Span<double> q, ref double cost, ref int budget, int maxSteps, double stallRatio)
    {
        var n = _n;
        var min = problem.Chain.MinRad;
        var max = problem.Chain.MaxRad;
        var damping = InitialDamping;
        var steps = 0;
        while (true)
        {
            if (problem.WithinTolerance())
            {
                return Outcome.Reached;
            }

            if (budget <= 0 || steps >= maxSteps)
            {
                return Outcome.OutOfBudget;
            }

            problem.NormalEquations(_jacobian, _normal, _jtr);
            var freeCount = 0;
            var gradient = 0.0;
            var largestDiagonal = 0.0;
            for (var i = 0; i < n; i++)
            {
                var g = _jtr[i];
                var atMinPushedOut = q[i] <= min[i] + BoundSlackRad && g > 0;
                var atMaxPushedOut = q[i] >= max[i] - BoundSlackRad && g < 0;
                var pinned = !_chain.IsFullTurn(i) && (atMinPushedOut || atMaxPushedOut);
                if (!pinned)
                {
                    _free[freeCount++] = i;
                    gradient = Math.Max(gradient, Math.Abs(g));
                    largestDiagonal = Math.Max(largestDiagonal, _normal[(i * n) + i]);
                }
            }

            // Stationary on the box (KKT point): nothing left to descend along.
            if (freeCount == 0 || !(gradient > 1e-14 * (1 + cost)) || !(largestDiagonal > 0))
            {
                return Outcome.Stalled;
            }

            var floor = 1e-9 * largestDiagonal;
            var accepted = false;
            while (!accepted)
            {
                if (!SolveDampedStep(freeCount, damping, floor))
                {
                    damping *= 8;
                    if (damping > MaxDamping)
                    {
                        return Outcome.Stalled;
                    }

                    continue;
                }

                var largestStep = 0.0;
                for (var f = 0; f < freeCount; f++)
                {
                    largestStep = Math.Max(largestStep, Math.Abs(_step[f]));
                }

                var scale = largestStep > MaxStepRad ? MaxStepRad / largestStep : 1.0;
                q.CopyTo(_trial);
                var moved = 0.0;
                for (var f = 0; f < freeCount; f++)
                {
                    var i = _free[f];
                    var value = _chain.IntoRange(i, q[i] + (scale * _step[f]));
                    moved = Math.Max(moved, Math.Abs(value - q[i]));
                    _trial[i] = value;
                }

                if (!(moved > 1e-15))
                {
                    return Outcome.Stalled;
                }

                var trialCost = problem.Evaluate(_trial);
                budget--;
                steps++;
                if (trialCost < cost)
                {
                    var gain = cost - trialCost;
                    _trial.AsSpan(0, n).CopyTo(q);
                    var previous = cost;
                    cost = trialCost;
                    damping = Math.Max(damping * 0.2, MinDamping);
                    accepted = true;
                    if (gain < stallRatio * previous && !problem.WithinTolerance())
                    {
                        return Outcome.Stalled;
                    }
                }
                else
                {
                    damping *= 8;
                    if (damping > MaxDamping || budget <= 0 || steps >= maxSteps)
                    {
                        problem.Evaluate(q);
                        return damping > MaxDamping ? Outcome.Stalled : Outcome.OutOfBudget;
                    }
                }
            }
        }
    }

    /// <summary>Solves (A_FF + λ diag(max(A_ii, floor))) δ = -(Jᵀr)_F by Cholesky; false if not positive definite.</summary>
    private bool SolveDampedStep(int freeCount, double damping, double floor)
    {
        var n = _n;
        var s = _system;
        for (var a = 0; a < freeCount; a++)
        {
            var i = _free[a];
            for (var b = 0; b <= a; b++)
            {
                s[(a * freeCount) + b] = _normal[(i * n) + _free[b]];
            }

            s[(a * freeCount) + a] += damping * Math.Max(_normal[(i * n) + i], floor);
        }

        // In-place Cholesky, lower triangle.
        for (var a = 0; a < freeCount; a++)
        {
            for (var b = 0; b <= a; b++)
            {
                var sum = s[(a * freeCount) + b];
                for (var k = 0; k < b; k++)
                {
                    sum -= s[(a * freeCount) + k] * s[(b * freeCount) + k];
                }

                if (a == b)
                {
                    if (!(sum > 0))
                    {
                        return false;
                    }

                    s[(a * freeCount) + a] = Math.Sqrt(sum);
                }
                else
                {
                    s[(a * freeCount) + b] = sum / s[(b * freeCount) + b];
                }
            }
        }

        for (var a = 0; a < freeCount; a++)
        {
            var sum = -_jtr[_free[a]];
            for (var k = 0; k < a; k++)
            {
                sum -= s[(a * freeCount) + k] * _step[k];
            }

            _step[a] = sum / s[(a * freeCount) + a];
        }

        for (var a = freeCount - 1; a >= 0; a--)
        {
            var sum = _step[a];
            for (var k = a + 1; k < freeCount; k++)
            {
                sum -= s[(k * freeCount) + a] * _step[k];
            }

            _step[a] = sum / s[(a * freeCount) + a];
        }

        for (var a = 0; a < freeCount; a++)
        {
            if (!double.IsFinite(_step[a]))
            {
                return false;
            }
        }

        return true;
    }
}
