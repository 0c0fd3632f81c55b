namespace RobotControl.Analysis.Plotting;

/// <summary>A perceptually ordered colour map (viridis, from nine of its published control colours, linearly interpolated).</summary>
public static class ColorMap
{
    private static readonly Rgb[] Stops =
    [
        new(68, 1, 84), new(71, 44, 122), new(59, 81, 139), new(44, 113, 142), new(33, 144, 141),
        new(39, 173, 129), new(92, 200, 99), new(170, 220, 50), new(253, 231, 37),
    ];

    /// <summary>Colour at <paramref name="t"/> in [0, 1] (clamped; NaN maps to the low end).</summary>
    public static Rgb At(double t)
    {
        t = double.IsNaN(t) ? 0 : Math.Clamp(t, 0, 1);
        var position = t * (Stops.Length - 1);
        var i = Math.Min((int)position, Stops.Length - 2);
        var f = position - i;
        var a = Stops[i];
        var b = Stops[i + 1];
        return new Rgb(Lerp(a.R, b.R, f), Lerp(a.G, b.G, f), Lerp(a.B, b.B, f));
    }

    private static byte Lerp(byte a, byte b, double f) => (byte)Math.Round(a + ((b - a) * f));
}
