namespace RobotControl.Analysis.Workspace;

/// <summary>
/// atan2 to about 1e-5 rad (Abramowitz &amp; Stegun 4.4.49 on [0, 1], folded into the octants): several times faster
/// than <see cref="Math.Atan2"/> and far finer than the angular bins it feeds (≥ 1e-3 rad).
/// </summary>
internal static class FastAngle
{
    public static double Atan2(double y, double x)
    {
        var ax = Math.Abs(x);
        var ay = Math.Abs(y);
        var max = Math.Max(ax, ay);
        if (max == 0)
        {
            return 0;
        }

        var z = Math.Min(ax, ay) / max;
        var z2 = z * z;
        var r = z * (0.9998660 + (z2 * (-0.3302995 + (z2 * (0.1801410 + (z2 * (-0.0851330 + (z2 * 0.0208351))))))));
        if (ay > ax)
        {
            r = (0.5 * Math.PI) - r;
        }

        if (x < 0)
        {
            r = Math.PI - r;
        }

        return y < 0 ? -r : r;
    }
}
