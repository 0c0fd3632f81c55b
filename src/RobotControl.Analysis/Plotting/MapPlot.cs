using System.Globalization;
using RobotControl.Analysis.Sweep;
using ScottPlot;
using ScottPlot.Plottables;

namespace RobotControl.Analysis.Plotting;

/// <summary>
/// Draws one sweep map with ScottPlot: a heatmap over the tool position (the sweep resampled onto a
/// <see cref="ToolPlaneGrid"/>; unreached cells transparent), equal scales on both axes in mm, a viridis colour bar
/// with units, the requirement's iso-line when the map crosses it, title "robot — quantity (units)", a subtitle with
/// the grid, method and min/mean/max.
/// </summary>
internal static class MapPlot
{
    /// <summary>Image width, pixels.</summary>
    public const int Width = 960;

    /// <summary>Image height, pixels.</summary>
    public const int Height = 780;

    private const int SubtitleCharacters = 130;
    private static readonly Color RequirementColour = new(220, 20, 60);

    /// <summary>
    /// Renders <paramref name="content"/> over <paramref name="plane"/> (built from <paramref name="sweep"/>) for robot
    /// <paramref name="robotName"/>; returns the PNG file's bytes.
    /// </summary>
    public static byte[] RenderPng(string robotName, string subtitle, SweepResult sweep, ToolPlaneGrid plane, MapContent content)
    {
        ArgumentNullException.ThrowIfNull(sweep);
        ArgumentNullException.ThrowIfNull(plane);
        ArgumentNullException.ThrowIfNull(content);
        PlotFont.Ensure();
        var stats = Statistics.Of(content.Values);

        using var plot = new Plot();
        var heatmap = plot.Add.Heatmap(plane.Resample(content.Values));
        heatmap.Colormap = new ScottPlot.Colormaps.Viridis();
        heatmap.NaNCellColor = Colors.Transparent;
        heatmap.Rectangle = new CoordinateRect(plane.Left, plane.Right, plane.Bottom, plane.Top);
        heatmap.ManualRange = stats.Max > stats.Min ? new ScottPlot.Range(stats.Min, stats.Max) : new ScottPlot.Range(stats.Min - 0.5, stats.Max + 0.5);

        var colourBar = plot.Add.ColorBar(heatmap);
        // The bar's own Label is drawn over wide tick labels; its axis label is placed outside them.
        colourBar.Axis.Label.Text = $"{content.Quantity} ({content.Units})";
        colourBar.Axis.Label.FontSize = 16;
        colourBar.Axis.Label.Bold = true;
        colourBar.MinimumSize = 110;

        var requirementText = AddRequirement(plot, sweep, plane, content, stats);

        plot.Title($"{robotName} — {content.Quantity} ({content.Units})", 22);
        plot.XLabel($"tool {plane.HorizontalName} (mm)", 16);
        plot.YLabel($"tool {plane.VerticalName} (mm)", 16);
        var statistics = string.Create(
            CultureInfo.InvariantCulture,
            $"min {Tidy(stats.Min, stats)}   mean {Tidy(stats.Mean, stats)}   max {Tidy(stats.Max, stats)} {content.Units}   ({sweep.Count} points){requirementText}");
        plot.Axes.AddPanel(Subtitle(string.Join('\n', Wrap($"{content.Description}; {subtitle}", SubtitleCharacters).Append(statistics))));
        plot.Axes.SetLimits(plane.Left, plane.Right, plane.Bottom, plane.Top);
        plot.Axes.SquareUnits();
        return plot.GetImageBytes(Width, Height, ImageFormat.Png);
    }

    /// <summary>Draws the requirement's iso-line when the map crosses it; returns the text for the statistics line.</summary>
    private static string AddRequirement(Plot plot, SweepResult sweep, ToolPlaneGrid plane, MapContent content, Statistics stats)
    {
        if (content.Requirement is not { } requirement)
        {
            return string.Empty;
        }

        var met = content.Values.Count(v => v >= requirement) / (double)content.Values.Count;
        var text = string.Create(CultureInfo.InvariantCulture, $";   requirement {requirement:G4} {content.Units}: met at {met:P1} of points");
        if (!(requirement > stats.Min && requirement < stats.Max))
        {
            return text;
        }

        var points = new Coordinates3d[sweep.XCount, sweep.YCount];
        var hs = sweep.Position[plane.HorizontalAxis];
        var vs = sweep.Position[plane.VerticalAxis];
        for (var ix = 0; ix < sweep.XCount; ix++)
        {
            for (var iy = 0; iy < sweep.YCount; iy++)
            {
                var i = (ix * sweep.YCount) + iy;
                points[ix, iy] = new Coordinates3d(hs[i], vs[i], content.Values[i]);
            }
        }

        var contour = plot.Add.ContourLines(points, 1);
        contour.ContourLineLevels = [requirement];
        contour.Update(points);
        contour.LineColor = RequirementColour;
        contour.LineWidth = 2.5f;
        contour.LinePattern = LinePattern.Dashed;
        contour.LabelStyle.IsVisible = false;
        return text + " (dashed line)";
    }

    /// <summary>
    /// <paramref name="value"/> to four significant digits, shown as 0 when it is rounding noise next to the map's largest
    /// magnitude (a speed of 2e-13 mm/s with the arm straight).
    /// </summary>
    private static string Tidy(double value, Statistics stats)
    {
        var scale = Math.Max(Math.Abs(stats.Min), Math.Abs(stats.Max));
        return (Math.Abs(value) < 1e-9 * scale ? 0 : value).ToString("G4", CultureInfo.InvariantCulture);
    }

    /// <summary>A second, smaller title panel (ScottPlot stacks title panels at the top).</summary>
    private static ScottPlot.Panels.TitlePanel Subtitle(string text)
    {
        var panel = new ScottPlot.Panels.TitlePanel();
        panel.Label.Text = text;
        panel.Label.FontSize = 12;
        panel.Label.Bold = false;
        return panel;
    }

    /// <summary>Splits <paramref name="text"/> at spaces into lines of at most <paramref name="maxChars"/> characters.</summary>
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
}
