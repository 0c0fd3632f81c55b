using System.Globalization;
using RobotControl.Analysis.Sweep;

namespace RobotControl.Analysis.Plotting;

/// <summary>What one map shows.</summary>
/// <param name="Values">One value per sweep point.</param>
/// <param name="Quantity">Short name, e.g. <c>Fx</c>.</param>
/// <param name="Description">What it is, e.g. <c>largest holding force along x</c>.</param>
/// <param name="Units">Units, e.g. <c>N</c> (empty for a dimensionless map).</param>
/// <param name="Requirement">A requirement to mark on the colour bar, or null.</param>
public sealed record MapContent(IReadOnlyList<double> Values, string Quantity, string Description, string Units, double? Requirement);

/// <summary>
/// Draws a sweep map over the tool position: the grid's cells are split into triangles and filled with the
/// linearly interpolated value, in the plane of the two base axes along which the swept tool positions spread most
/// (the reference cross-sections lie in the base x-y plane). Equal scales on both axes, ticks in mm, a colour bar
/// with units (and the requirement marked when there is one), the robot and quantity in the title.
/// </summary>
public static class MapPlot
{
    private const int Width = 960;
    private const int Height = 780;
    private const int Left = 110;
    private const int Right = 200;
    private const int Top = 90;
    private const int Bottom = 110;
    private static readonly string[] AxisNames = ["x", "y", "z"];
    private static readonly Rgb Ink = Rgb.Grey(20);
    private static readonly Rgb Requirement = new(220, 20, 60);

    /// <summary>Renders <paramref name="content"/> over the sweep <paramref name="sweep"/> of robot <paramref name="robotName"/>.</summary>
    public static RgbImage Render(string robotName, string subtitle, SweepResult sweep, MapContent content)
    {
        ArgumentNullException.ThrowIfNull(sweep);
        ArgumentNullException.ThrowIfNull(content);
        if (content.Values.Count != sweep.Count)
        {
            throw new ArgumentException($"the map has {content.Values.Count} values; the sweep has {sweep.Count} points", nameof(content));
        }

        var (ha, va) = PlotPlane(sweep);
        var hs = sweep.Position[ha];
        var vs = sweep.Position[va];
        var (hMin, hMax) = Padded(hs);
        var (vMin, vMax) = Padded(vs);
        var plotW = Width - Left - Right;
        var plotH = Height - Top - Bottom;
        var scale = Math.Min(plotW / (hMax - hMin), plotH / (vMax - vMin));
        var boxW = (int)Math.Round((hMax - hMin) * scale);
        var boxH = (int)Math.Round((vMax - vMin) * scale);
        var boxX = Left + ((plotW - boxW) / 2);
        var boxY = Top + ((plotH - boxH) / 2);
        double Px(double h) => boxX + ((h - hMin) * scale);
        double Py(double v) => boxY + boxH - ((v - vMin) * scale);

        var stats = Statistics.Of(content.Values);
        var lo = stats.Min;
        var hi = stats.Max > stats.Min ? stats.Max : stats.Min + 1;
        var image = new RgbImage(Width, Height);

        // Map: two triangles per grid cell, colour from the interpolated value.
        for (var ix = 0; ix + 1 < sweep.XCount; ix++)
        {
            for (var iy = 0; iy + 1 < sweep.YCount; iy++)
            {
                var a = (ix * sweep.YCount) + iy;
                var b = a + sweep.YCount;
                var c = b + 1;
                var d = a + 1;
                FillTriangle(image, content.Values, lo, hi, (Px(hs[a]), Py(vs[a]), a), (Px(hs[b]), Py(vs[b]), b), (Px(hs[c]), Py(vs[c]), c));
                FillTriangle(image, content.Values, lo, hi, (Px(hs[a]), Py(vs[a]), a), (Px(hs[c]), Py(vs[c]), c), (Px(hs[d]), Py(vs[d]), d));
            }
        }

        // Axes box, ticks and labels.
        image.DrawRectangle(boxX, boxY, boxW + 1, boxH + 1, Ink);
        var hTicks = NiceTicks.For(hMin, hMax, Math.Max(2, boxW / 80));
        foreach (var t in hTicks)
        {
            var x = (int)Math.Round(Px(t));
            image.DrawLine(x, boxY + boxH, x, boxY + boxH + 6, Ink);
            var label = NiceTicks.Format(t, hTicks);
            BitmapFont.Draw(image, label, x - (BitmapFont.MeasureWidth(label, 2) / 2), boxY + boxH + 12, 2, Ink);
        }

        var vTicks = NiceTicks.For(vMin, vMax, Math.Max(2, boxH / 60));
        foreach (var t in vTicks)
        {
            var y = (int)Math.Round(Py(t));
            image.DrawLine(boxX - 6, y, boxX, y, Ink);
            var label = NiceTicks.Format(t, vTicks);
            BitmapFont.Draw(image, label, boxX - 10 - BitmapFont.MeasureWidth(label, 2), y - 7, 2, Ink);
        }

        var hLabel = $"tool {AxisNames[ha]} [mm]";
        BitmapFont.Draw(image, hLabel, boxX + ((boxW - BitmapFont.MeasureWidth(hLabel, 2)) / 2), boxY + boxH + 40, 2, Ink);
        var vLabel = $"tool {AxisNames[va]} [mm]";
        BitmapFont.DrawVertical(image, vLabel, 20, boxY + ((boxH - BitmapFont.MeasureWidth(vLabel, 2)) / 2), 2, Ink);

        // Title and statistics.
        var unitsText = content.Units.Length > 0 ? $" [{content.Units}]" : string.Empty;
        BitmapFont.Draw(image, $"{robotName}: {content.Quantity}{unitsText}, {content.Description}", 20, 16, 2, Ink);
        var lineY = 44;
        foreach (var line in Wrap(subtitle, (Width - 40) / BitmapFont.Advance))
        {
            BitmapFont.Draw(image, line, 20, lineY, 1, Ink);
            lineY += 10;
        }

        var statsText = string.Create(
            CultureInfo.InvariantCulture,
            $"min {stats.Min:G4}   mean {stats.Mean:G4}   max {stats.Max:G4} {content.Units}   ({sweep.Count} points)");
        BitmapFont.Draw(image, statsText, 20, Height - 30, 2, Ink);

        DrawColourBar(image, boxX + boxW + 40, boxY, boxH, lo, hi, content);
        return image;
    }

    /// <summary>The two base axes (0 = x, 1 = y, 2 = z) along which the tool positions spread most, in axis order.</summary>
    public static (int Horizontal, int Vertical) PlotPlane(SweepResult sweep)
    {
        ArgumentNullException.ThrowIfNull(sweep);
        var spread = sweep.Position.Select(p => p.Max() - p.Min()).ToArray();
        var smallest = Array.IndexOf(spread, spread.Min());
        var axes = Enumerable.Range(0, 3).Where(a => a != smallest).ToArray();
        return (axes[0], axes[1]);
    }

    private static void DrawColourBar(RgbImage image, int x, int y, int height, double lo, double hi, MapContent content)
    {
        const int barWidth = 26;
        for (var row = 0; row < height; row++)
        {
            var colour = ColorMap.At(1.0 - ((double)row / Math.Max(1, height - 1)));
            image.FillRectangle(x, y + row, barWidth, 1, colour);
        }

        image.DrawRectangle(x - 1, y - 1, barWidth + 2, height + 2, Ink);
        int Row(double v) => y + (int)Math.Round((1 - ((v - lo) / (hi - lo))) * (height - 1));
        var ticks = NiceTicks.For(lo, hi, 8);
        foreach (var t in ticks)
        {
            var r = Row(t);
            image.DrawLine(x + barWidth, r, x + barWidth + 5, r, Ink);
            BitmapFont.Draw(image, NiceTicks.Format(t, ticks), x + barWidth + 9, r - 7, 2, Ink);
        }

        var unitsLabel = content.Units.Length > 0 ? $"{content.Quantity} [{content.Units}]" : content.Quantity;
        BitmapFont.Draw(image, unitsLabel, x - 10, y - 26, 2, Ink);
        if (content.Requirement is { } requirement && requirement >= lo && requirement <= hi)
        {
            var r = Row(requirement);
            image.FillRectangle(x - 6, r - 1, barWidth + 12, 3, Requirement);
            BitmapFont.Draw(image, "req", x - 44, r - 7, 2, Requirement);
        }
        else if (content.Requirement is { } outside)
        {
            var text = string.Create(CultureInfo.InvariantCulture, $"req {outside:G3}: {(outside > hi ? "met nowhere" : "met everywhere")}");
            BitmapFont.Draw(image, text, x - 20, y + height + 24, 2, Requirement);
        }
    }

    private static IEnumerable<string> Wrap(string text, int maxChars)
    {
        var line = string.Empty;
        foreach (var word in text.Split(' '))
        {
            if (line.Length > 0 && line.Length + 1 + word.Length > maxChars)
            {
                yield return line;
                line = word;
            }
            else
            {
                line = line.Length == 0 ? word : $"{line} {word}";
            }
        }

        if (line.Length > 0)
        {
            yield return line;
        }
    }

    private static (double Min, double Max) Padded(double[] values)
    {
        var min = values.Min();
        var max = values.Max();
        var pad = Math.Max(0.03 * (max - min), 1.0);
        return (min - pad, max + pad);
    }

    private static void FillTriangle(
        RgbImage image,
        IReadOnlyList<double> values,
        double lo,
        double hi,
        (double X, double Y, int I) p0,
        (double X, double Y, int I) p1,
        (double X, double Y, int I) p2)
    {
        var area = ((p1.X - p0.X) * (p2.Y - p0.Y)) - ((p2.X - p0.X) * (p1.Y - p0.Y));
        var minX = (int)Math.Floor(Math.Min(p0.X, Math.Min(p1.X, p2.X)));
        var maxX = (int)Math.Ceiling(Math.Max(p0.X, Math.Max(p1.X, p2.X)));
        var minY = (int)Math.Floor(Math.Min(p0.Y, Math.Min(p1.Y, p2.Y)));
        var maxY = (int)Math.Ceiling(Math.Max(p0.Y, Math.Max(p1.Y, p2.Y)));
        if (Math.Abs(area) < 1e-12)
        {
            return;
        }

        var (v0, v1, v2) = (values[p0.I], values[p1.I], values[p2.I]);
        const double edge = -1e-9;
        for (var py = minY; py <= maxY; py++)
        {
            for (var px = minX; px <= maxX; px++)
            {
                double cx = px + 0.5, cy = py + 0.5;
                var w0 = (((p1.X - cx) * (p2.Y - cy)) - ((p2.X - cx) * (p1.Y - cy))) / area;
                var w1 = (((p2.X - cx) * (p0.Y - cy)) - ((p0.X - cx) * (p2.Y - cy))) / area;
                var w2 = 1 - w0 - w1;
                if (w0 < edge || w1 < edge || w2 < edge)
                {
                    continue;
                }

                var value = (w0 * v0) + (w1 * v1) + (w2 * v2);
                image.SetPixel(px, py, ColorMap.At((value - lo) / (hi - lo)));
            }
        }
    }
}
