using System.Numerics;
using System.Runtime.InteropServices;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Inverse;

/// <summary>
/// The solver's fallback starts: a fixed set of joint vectors spread over the joint box, with their tool poses computed
/// once. When a run stalls, the next start is the unused seed whose pose is nearest the target (by the solver's own
/// cost), so a restart begins close to the answer instead of anywhere: this is what solves the corners of the
/// workspace (shoulder joints at their limits and near alignment) that uniform random restarts rarely land near.
/// </summary>
/// <remarks>
/// The set: every corner of the box taken 5 % in from each limit (for up to <see cref="MaxCornerJoints"/> joints), then
/// Halton points (bases 2, 3, 5, ...) to <see cref="Count"/>. Deterministic, so a solve is reproducible. Allocates only in
/// the constructor. Ranking is one pass over the set (poses stored column by column, so the pass streams through
/// memory) that keeps the <see cref="Kept"/> nearest (a bounded heap, then sorted); <see cref="Next"/> then takes them one by one.
/// </remarks>
internal sealed class RestartSeeds
{
    /// <summary>Seeds in the set (a multiple of every SIMD width, so the ranking has no remainder).</summary>
    internal const int Count = 1024;

    /// <summary>Corners are included while there are at most 2^7 = 128 of them.</summary>
    internal const int MaxCornerJoints = 7;

    private const double CornerInset = 0.05;
    private static readonly int[] Primes = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53];

    /// <summary>Nearest seeds kept by <see cref="Rank"/>; restarts beyond this many take them again from the nearest.</summary>
    internal const int Kept = 48;

    private readonly int _n;
    private readonly double[] _joints;

    // The seeds' tool poses, one array per coordinate: position x, y, z, then the rotation's columns (x, y, z axes).
    private readonly double[][] _pose;
    private readonly double[] _cost = new double[Count];
    private readonly double[] _keptCost = new double[Kept];
    private readonly int[] _kept = new int[Kept];
    private int _keptCount;
    private int _next;

    internal RestartSeeds(KinematicChain chain, ReadOnlySpan<double> low, ReadOnlySpan<double> high)
    {
        _n = chain.JointCount;
        _joints = new double[Count * _n];
        _pose = new double[12][];
        for (var c = 0; c < _pose.Length; c++)
        {
            _pose[c] = new double[Count];
        }
        var corners = _n <= MaxCornerJoints ? 1 << _n : 0;
        var state = chain.CreateState();
        for (var s = 0; s < Count; s++)
        {
            var q = _joints.AsSpan(s * _n, _n);
            for (var i = 0; i < _n; i++)
            {
                var fraction = s < corners
                    ? (((s >> i) & 1) == 0 ? CornerInset : 1 - CornerInset)
                    : RadicalInverse(s - corners + 1, Primes[i % Primes.Length]);
                q[i] = Math.Clamp(low[i] + (fraction * (high[i] - low[i])), chain.MinRad[i], chain.MaxRad[i]);
            }

            state.Update(q);
            var rotation = state.ToolRotation;
            Store(s, 0, state.ToolPosition);
            Store(s, 3, rotation.X);
            Store(s, 6, rotation.Y);
            Store(s, 9, rotation.Z);
        }
    }

    /// <summary>
    /// Scores every seed against the problem's current target by the solver's cost (<see cref="IkProblem.CurrentCost"/>,
    /// wp |p - Pd|² + wo Σ |Rh_j - Rd_j|², here over the stored poses) and keeps the nearest in order; call once per solve, before the first <see cref="Next"/>.
    /// </summary>
    internal void Rank(IkProblem problem)
    {
        var target = problem.TargetPosition;
        var cost = _cost.AsSpan();
        cost.Clear();
        AddSquaredDistance(cost, 0, target, problem.PositionWeight);
        for (var k = 0; k < problem.AxisCount; k++)
        {
            AddSquaredDistance(cost, 3 + (3 * problem.SelectedColumn(k)), problem.TargetAxis(k), problem.OrientationWeight);
        }

        // The nearest Kept by a bounded max-heap (the farthest kept on top), then in order.
        _keptCount = 0;
        _next = 0;
        for (var s = 0; s < Count; s++)
        {
            if (_keptCount < Kept)
            {
                Push(s, cost[s]);
            }
            else if (cost[s] < _keptCost[0])
            {
                ReplaceTop(s, cost[s]);
            }
        }

        _keptCost.AsSpan(0, _keptCount).Sort(_kept.AsSpan(0, _keptCount));
    }

    /// <summary>Writes the nearest seed not yet taken since <see cref="Rank"/> to <paramref name="q"/> (after the kept ones, from the nearest again).</summary>
    internal void Next(Span<double> q)
    {
        var seed = _kept[_next % Math.Max(_keptCount, 1)];
        _next++;
        _joints.AsSpan(seed * _n, _n).CopyTo(q);
    }

    /// <summary>Writes seed <paramref name="s"/> of the set (in the set's own order) to <paramref name="q"/>; for tests.</summary>
    internal void SeedAt(int s, Span<double> q) => _joints.AsSpan(s * _n, _n).CopyTo(q);

    private void Push(int s, double cost)
    {
        var at = _keptCount++;
        while (at > 0)
        {
            var parent = (at - 1) / 2;
            if (!(cost > _keptCost[parent]))
            {
                break;
            }

            _keptCost[at] = _keptCost[parent];
            _kept[at] = _kept[parent];
            at = parent;
        }

        _keptCost[at] = cost;
        _kept[at] = s;
    }

    private void ReplaceTop(int s, double cost)
    {
        var at = 0;
        while (true)
        {
            var child = (2 * at) + 1;
            if (child >= _keptCount)
            {
                break;
            }

            if (child + 1 < _keptCount && _keptCost[child + 1] > _keptCost[child])
            {
                child++;
            }

            if (!(_keptCost[child] > cost))
            {
                break;
            }

            _keptCost[at] = _keptCost[child];
            _kept[at] = _kept[child];
            at = child;
        }

        _keptCost[at] = cost;
        _kept[at] = s;
    }

    /// <summary>cost[s] += weight |v_s - to|², v_s the 3-vector of columns column..column+2, four seeds at a time.</summary>
    private void AddSquaredDistance(Span<double> cost, int column, Vector3d to, double weight)
    {
        var xs = MemoryMarshal.Cast<double, Vector<double>>(_pose[column]);
        var ys = MemoryMarshal.Cast<double, Vector<double>>(_pose[column + 1]);
        var zs = MemoryMarshal.Cast<double, Vector<double>>(_pose[column + 2]);
        var sums = MemoryMarshal.Cast<double, Vector<double>>(cost);
        var tx = new Vector<double>(to.X);
        var ty = new Vector<double>(to.Y);
        var tz = new Vector<double>(to.Z);
        var w = new Vector<double>(weight);
        for (var g = 0; g < sums.Length; g++)
        {
            var dx = xs[g] - tx;
            var dy = ys[g] - ty;
            var dz = zs[g] - tz;
            sums[g] += w * ((dx * dx) + (dy * dy) + (dz * dz));
        }
    }

    private void Store(int s, int column, Vector3d v)
    {
        _pose[column][s] = v.X;
        _pose[column + 1][s] = v.Y;
        _pose[column + 2][s] = v.Z;
    }

    /// <summary>The index-th element of the van der Corput sequence in <paramref name="radix"/>, in (0, 1).</summary>
    private static double RadicalInverse(int index, int radix)
    {
        var result = 0.0;
        var scale = 1.0 / radix;
        for (var i = index; i > 0; i /= radix)
        {
            result += (i % radix) * scale;
            scale /= radix;
        }

        return result;
    }
}
