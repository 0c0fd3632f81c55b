using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Inverse;

/// <summary>
/// Escapes from the trap of a singular pose. Where two joint axes lie on one line (the LB-1.0's shoulder roll and tool
/// roll with the elbow straight; its yaw and roll with the pitch at −90°), turning one joint by δ and the other by ∓δ
/// leaves the tool where it is: the pose has a free direction that the Newton step cannot see, and a run that stalls
/// there with a joint on its limit stays stuck (the answer needs the elbow to bend the other way, say). From such a
/// stalled pose this proposes hops along that free direction, to spread points of the first joint's range, each
/// with the pose unchanged (both joints kept within their ranges); the solver restarts from them before it tries the distant fixed seeds.
/// </summary>
internal sealed class AlignedAxisHops
{
    /// <summary>Hops proposed per stalled pose at most.</summary>
    internal const int MaxHops = 8;

    private const double ParallelSine = 0.035; // 2°
    private const double LineDistanceMm = 1.0;
    private static readonly double[] Spread = [0.98, 0.02, 0.5];

    private readonly KinematicChain _chain;
    private readonly ReadOnlyMemory<double> _low;
    private readonly ReadOnlyMemory<double> _high;
    private readonly double[] _hops;
    private int _count;
    private int _next;

    internal AlignedAxisHops(KinematicChain chain, double[] low, double[] high)
    {
        _chain = chain;
        _low = low;
        _high = high;
        _hops = new double[MaxHops * chain.JointCount];
    }

    /// <summary>Hops left from the last <see cref="Propose"/>.</summary>
    internal bool Any => _next < _count;

    /// <summary>Forgets the hops of the previous solve.</summary>
    internal void Clear() => _count = _next = 0;

    /// <summary>
    /// Proposes hops from <paramref name="q"/>, whose frames <paramref name="state"/> holds; returns how many.
    /// </summary>
    internal int Propose(ChainState state, ReadOnlySpan<double> q)
    {
        _count = _next = 0;
        var n = _chain.JointCount;
        var low = _low.Span;
        var high = _high.Span;
        for (var i = 0; i < n && _count < MaxHops; i++)
        {
            var axisI = state.JointAxis(i);
            var originI = state.JointOrigin(i);
            for (var j = i + 1; j < n && _count < MaxHops; j++)
            {
                // On one line: within 2° of parallel, and j's origin off i's line by no more than that angle allows
                // over the distance between them (plus a millimetre).
                var axisJ = state.JointAxis(j);
                var between = state.JointOrigin(j) - originI;
                if (Vector3d.Cross(axisI, axisJ).Length > ParallelSine
                    || Vector3d.Cross(between, axisI).Length > LineDistanceMm + (ParallelSine * between.Length))
                {
                    continue;
                }

                // Same line: turning i by δ and j by -sδ (s = ±1 as the axes point the same way or not) keeps the tool.
                // δ is spread over the interval that keeps both joints within their ranges, its far ends first.
                var sign = Vector3d.Dot(axisI, axisJ) > 0 ? 1.0 : -1.0;
                var deltaLow = low[i] - q[i];
                var deltaHigh = high[i] - q[i];
                if (!_chain.IsFullTurn(j))
                {
                    var a = sign * (q[j] - high[j]);
                    var b = sign * (q[j] - low[j]);
                    deltaLow = Math.Max(deltaLow, Math.Min(a, b));
                    deltaHigh = Math.Min(deltaHigh, Math.Max(a, b));
                }

                foreach (var fraction in Spread)
                {
                    var delta = deltaLow + (fraction * (deltaHigh - deltaLow));
                    if (_count == MaxHops || !(Math.Abs(delta) >= 0.1 * (high[i] - low[i])))
                    {
                        continue;
                    }

                    var hop = _hops.AsSpan(_count * n, n);
                    q.CopyTo(hop);
                    hop[i] = Math.Clamp(q[i] + delta, _chain.MinRad[i], _chain.MaxRad[i]);
                    hop[j] = _chain.IntoRange(j, q[j] - (sign * delta));
                    _count++;
                }
            }
        }

        return _count;
    }

    /// <summary>Writes the next hop to <paramref name="q"/>.</summary>
    internal void Next(Span<double> q)
    {
        var n = _chain.JointCount;
        _hops.AsSpan(_next * n, n).CopyTo(q);
        _next++;
    }
}
