using MathNet.Numerics.LinearAlgebra;
using MathNet.Numerics.Optimization;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Bench.Ik;

/// <summary>
/// The baseline: the reference design's algorithm as docs/algorithms.md describes it, kept faithful on purpose. CCD cycles
/// (joints last to first, analytic k1/k2/k3 step, clamp to the joint's limits, frames recomputed after every joint) up
/// to 15,000 cycles; once E falls below the switch threshold, an L-BFGS minimisation of E with the analytic gradient
/// (MathNet's LimitedMemoryBfgsMinimizer standing in for ALGLIB minlbfgs, which is not served), unconstrained, with the
/// result clamped to the joint limits afterwards.
/// </summary>
internal sealed class ReferenceIkSolver
{
    /// <summary>CCD cycle cap of the reference design.</summary>
    public const int MaxCcdCycles = 15_000;

    /// <summary>E below which CCD hands over to L-BFGS (mm²; the reference value is not recorded, 1 mm² chosen).</summary>
    public const double SwitchThreshold = 1.0;

    /// <summary>E below which the solve stops (mm²: 1e-4 mm² is a tenth of the 0.01 mm per-axis position tolerance).</summary>
    public const double StopThreshold = 1e-5;

    private readonly KinematicChain _chain;
    private readonly ChainState _state;
    private readonly double _wp;
    private readonly double _wo;
    private IkTarget _target;

    public ReferenceIkSolver(KinematicChain chain, IkOptions options)
    {
        _chain = chain;
        _state = chain.CreateState();
        _wp = options.PositionWeight;
        _wo = options.OrientationWeight;
    }

    public void Solve(in IkTarget target, ReadOnlySpan<double> seed, Span<double> solution)
    {
        _target = target;
        var n = _chain.JointCount;
        var q = seed[..n].ToArray();
        var e = Error(q);
        for (var cycle = 0; cycle < MaxCcdCycles && e >= StopThreshold && e >= SwitchThreshold; cycle++)
        {
            CcdCycle(q);
            e = Error(q);
        }

        if (e >= StopThreshold && e < SwitchThreshold)
        {
            q = Lbfgs(q);
        }

        _chain.Clamp(q);
        q.CopyTo(solution);
    }

    private void CcdCycle(double[] q)
    {
        for (var i = _chain.JointCount - 1; i >= 0; i--)
        {
            _state.Update(q);
            var z = _state.JointAxis(i);
            var origin = _state.JointOrigin(i);
            var pih = _state.ToolPosition - origin;
            var pid = _target.Position - origin;
            var k1 = _wp * Vector3d.Dot(pid, z) * Vector3d.Dot(pih, z);
            var k2 = _wp * Vector3d.Dot(pid, pih);
            var k3v = Vector3d.Cross(pih, pid) * _wp;
            var rotation = _state.ToolRotation;
            for (var j = 0; j < 3; j++)
            {
                if (((int)_target.AxisMask & (1 << j)) == 0)
                {
                    continue;
                }

                var rh = rotation[j];
                var rd = _target.Rotation[j];
                k1 += _wo * Vector3d.Dot(rd, z) * Vector3d.Dot(rh, z);
                k2 += _wo * Vector3d.Dot(rd, rh);
                k3v += Vector3d.Cross(rh, rd) * _wo;
            }

            var k3 = Vector3d.Dot(z, k3v);
            var phi = Math.Atan(k3 / (k2 - k1));
            if (double.IsNaN(phi))
            {
                continue;
            }

            // tan has two roots a half turn apart: keep the maximum, d2g/dphi2 = (k1 - k2) cos - k3 sin < 0.
            if (((k1 - k2) * Math.Cos(phi)) - (k3 * Math.Sin(phi)) > 0)
            {
                phi += phi > 0 ? -Math.PI : Math.PI;
            }

            q[i] = Math.Clamp(q[i] + phi, _chain.MinRad[i], _chain.MaxRad[i]);
        }
    }

    private double Error(ReadOnlySpan<double> q)
    {
        _state.Update(q);
        var e = _wp * (_target.Position - _state.ToolPosition).LengthSquared;
        var rotation = _state.ToolRotation;
        for (var j = 0; j < 3; j++)
        {
            if (((int)_target.AxisMask & (1 << j)) != 0)
            {
                var c = Vector3d.Dot(_target.Rotation[j], rotation[j]) - 1;
                e += _wo * c * c;
            }
        }

        return e;
    }

    private (double Value, Vector<double> Gradient) ErrorAndGradient(Vector<double> x)
    {
        var q = x.ToArray();
        var e = Error(q);
        var end = _state.ToolPosition;
        var toTarget = _target.Position - end;
        var rotation = _state.ToolRotation;
        var gradient = Vector<double>.Build.Dense(q.Length);
        for (var i = 0; i < q.Length; i++)
        {
            var z = _state.JointAxis(i);
            var pih = end - _state.JointOrigin(i);
            var g = -2 * _wp * Vector3d.Dot(z, Vector3d.Cross(pih, toTarget));
            for (var j = 0; j < 3; j++)
            {
                if (((int)_target.AxisMask & (1 << j)) != 0)
                {
                    var rh = rotation[j];
                    var rd = _target.Rotation[j];
                    g += _wo * 2 * (Vector3d.Dot(rd, rh) - 1) * Vector3d.Dot(z, Vector3d.Cross(rh, rd));
                }
            }

            gradient[i] = g;
        }

        return (e, gradient);
    }

    private double[] Lbfgs(double[] start)
    {
        var best = (double[])start.Clone();
        var bestValue = Error(start);
        var objective = ObjectiveFunction.Gradient(x =>
        {
            var (value, gradient) = ErrorAndGradient(x);
            if (value < bestValue)
            {
                bestValue = value;
                for (var i = 0; i < best.Length; i++)
                {
                    best[i] = x[i];
                }
            }

            return (value, gradient);
        });
        try
        {
            var minimizer = new LimitedMemoryBfgsMinimizer(1e-12, 1e-14, 1e-16, 5, 1000);
            var result = minimizer.FindMinimum(objective, Vector<double>.Build.Dense(start));
            return result.MinimizingPoint.ToArray();
        }
        catch (Exception ex) when (ex is OptimizationException or ArithmeticException or ArgumentException)
        {
            // minlbfgs reports a stop rather than throwing; keep the best point it evaluated.
            return best;
        }
    }
}
