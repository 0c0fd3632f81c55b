using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Inverse;

/// <summary>
/// One cycle of cyclic coordinate descent with the analytic per-joint step of docs/algorithms.md: joints from last to first,
/// each rotated by the φ maximising g(φ) = k1 (1 - cos φ) + k2 cos φ + k3 sin φ, restricted to the joint's range.
/// </summary>
internal static class CyclicCoordinateDescent
{
    /// <summary>
    /// Runs one cycle on <paramref name="q"/> (within limits on entry and exit). Expects the problem's state to hold the
    /// frames of <paramref name="q"/>; leaves it holding the frames of the updated q. Returns the least-squares cost.
    /// </summary>
    internal static double Cycle(IkProblem problem, Span<double> q)
    {
        var state = problem.State;
        var chain = problem.Chain;
        var wp = problem.PositionWeight;
        var wo = problem.OrientationWeight;
        var pd = problem.TargetPosition;
        var axisCount = problem.AxisCount;
        var end = state.ToolPosition;
        var rotation = state.ToolRotation;
        Span<Vector3d> rh = stackalloc Vector3d[3];
        for (var k = 0; k < axisCount; k++)
        {
            rh[k] = rotation[problem.SelectedColumn(k)];
        }

        // Joints before i do not move when joint i turns, so their frames stay valid; only the tool pose changes,
        // and it is rotated in place (Rodrigues) instead of re-running the recursion per joint.
        for (var i = problem.JointCount - 1; i >= 0; i--)
        {
            var z = state.JointAxis(i);
            var origin = state.JointOrigin(i);
            var pih = end - origin;
            var pid = pd - origin;
            var k1 = wp * Vector3d.Dot(pid, z) * Vector3d.Dot(pih, z);
            var k2 = wp * Vector3d.Dot(pid, pih);
            var k3v = Vector3d.Cross(pih, pid) * wp;
            for (var k = 0; k < axisCount; k++)
            {
                var rd = problem.TargetAxis(k);
                k1 += wo * Vector3d.Dot(rd, z) * Vector3d.Dot(rh[k], z);
                k2 += wo * Vector3d.Dot(rd, rh[k]);
                k3v += Vector3d.Cross(rh[k], rd) * wo;
            }

            var k3 = Vector3d.Dot(z, k3v);
            var phi = BestStep(k1, k2, k3, q[i], chain.MinRad[i], chain.MaxRad[i]);
            if (phi == 0)
            {
                continue;
            }

            var turned = Math.Clamp(q[i] + phi, chain.MinRad[i], chain.MaxRad[i]);
            phi = turned - q[i];
            q[i] = turned;
            var (s, c) = Math.SinCos(phi);
            end = origin + Rotate(pih, z, s, c);
            for (var k = 0; k < axisCount; k++)
            {
                rh[k] = Rotate(rh[k], z, s, c);
            }
        }

        return problem.Evaluate(q);
    }

    /// <summary>
    /// The φ maximising g over q + φ within [min, max]: the unconstrained maximum φ* = atan2(k3, k2 - k1) (where
    /// g'' = (k1 - k2) cos φ - k3 sin φ &lt; 0) or any of its 2π images inside the range; otherwise the better end of the
    /// range, since g is a single sinusoid in φ.
    /// </summary>
    internal static double BestStep(double k1, double k2, double k3, double q, double min, double max)
    {
        var a = k2 - k1;

        // A joint that cannot change g (e.g. a tool roll about the tool's own position axis) stays put: its
        // amplitude is rounding noise, and atan2 of noise is a random angle.
        var amplitude = Math.Abs(a) + Math.Abs(k3);
        if (!(amplitude > 1e-12 * (Math.Abs(k1) + Math.Abs(k2) + Math.Abs(k3))) || !double.IsFinite(amplitude))
        {
            return 0;
        }

        var best = Math.Atan2(k3, a);
        var candidate = q + best;
        if (candidate < min || candidate > max)
        {
            var turns = Math.Round((q + best - (0.5 * (min + max))) / (2 * Math.PI));
            candidate = q + best - (turns * 2 * Math.PI);
        }

        if (candidate >= min && candidate <= max)
        {
            return candidate - q;
        }

        var toMin = min - q;
        var toMax = max - q;
        var gMin = (a * Math.Cos(toMin)) + (k3 * Math.Sin(toMin));
        var gMax = (a * Math.Cos(toMax)) + (k3 * Math.Sin(toMax));
        return gMin >= gMax ? toMin : toMax;
    }

    private static Vector3d Rotate(Vector3d v, Vector3d axis, double s, double c) =>
        (v * c) + (Vector3d.Cross(axis, v) * s) + (axis * (Vector3d.Dot(axis, v) * (1 - c)));
}
