using System.Globalization;
using RobotControl.Analysis.Plotting;
using RobotControl.Analysis.Sweep;

namespace RobotControl.Analysis.Output;

/// <summary>
/// Writes an analysis into a directory: <c>summary.json</c>, <c>sweep.csv</c> and the PNG maps. Everything is first
/// written into a hidden staging directory beside the target and moved in only when all files exist, so a failure
/// leaves the target untouched.
/// </summary>
public static class AnalysisOutputWriter
{
    /// <summary>Map file names (without the coupling-aware ones) in the order they are written.</summary>
    public static IReadOnlyList<string> MapFiles { get; } =
        ["manipulability.png", "vx.png", "vy.png", "vz.png", "fx.png", "fy.png", "fz.png"];

    /// <summary>Writes every output of <paramref name="report"/> into <paramref name="directory"/> (created if missing); returns the files' paths.</summary>
    /// <exception cref="InvalidOperationException">The maps' font is not installed (checked before anything is written).</exception>
    public static IReadOnlyList<string> Write(AnalysisReport report, string directory, IProgress<AnalysisProgress>? progress = null)
    {
        ArgumentNullException.ThrowIfNull(report);
        ArgumentException.ThrowIfNullOrEmpty(directory);
        PlotFont.Ensure();
        var target = Path.GetFullPath(directory);
        var parent = Path.GetDirectoryName(target.TrimEnd(Path.DirectorySeparatorChar)) ?? target;
        Directory.CreateDirectory(parent);
        var staging = Path.Combine(parent, $".{Path.GetFileName(target.TrimEnd(Path.DirectorySeparatorChar))}.partial-{Guid.NewGuid():N}");
        Directory.CreateDirectory(staging);
        try
        {
            var files = new List<(string Name, byte[] Bytes)>
            {
                ("summary.json", SummaryJsonWriter.Write(report)),
                ("sweep.csv", SweepCsvWriter.Write(report)),
            };
            var maps = Maps(report).ToArray();
            var images = new byte[maps.Length][];
            var plane = ToolPlaneGrid.For(report.Sweep);
            var done = 0;

            // Maps are independent: render them on every core.
            Parallel.For(0, maps.Length, i =>
            {
                var (name, content) = maps[i];
                images[i] = MapPlot.RenderPng(report.Robot.Name, Subtitle(report, name), report.Sweep, plane, content);
                var finished = Interlocked.Increment(ref done);
                progress?.Report(new AnalysisProgress($"map {name}", 0.9 + (0.1 * finished / maps.Length), null));
            });
            files.AddRange(maps.Select((m, i) => (m.File, images[i])));

            foreach (var (name, bytes) in files)
            {
                File.WriteAllBytes(Path.Combine(staging, name), bytes);
            }

            Directory.CreateDirectory(target);
            var written = new List<string>();
            foreach (var (name, _) in files)
            {
                var destination = Path.Combine(target, name);
                File.Move(Path.Combine(staging, name), destination, overwrite: true);
                written.Add(destination);
            }

            return written;
        }
        finally
        {
            Directory.Delete(staging, recursive: true);
        }
    }

    private static IEnumerable<(string File, MapContent Content)> Maps(AnalysisReport report)
    {
        var sweep = report.Sweep;
        var req = report.Robot.Requirements;
        double[] force = [req.ForceN.X, req.ForceN.Y, req.ForceN.Z];
        double[] velocity = [req.VelocityMmPerS.X, req.VelocityMmPerS.Y, req.VelocityMmPerS.Z];
        string[] axes = ["x", "y", "z"];
        var wMax = sweep.Manipulability.Max();
        yield return (
            "manipulability.png",
            new MapContent(
                sweep.ManipulabilityNormalised,
                "manipulability w/w_max",
                string.Create(CultureInfo.InvariantCulture, $"manipulability w = sqrt(det(J Jᵀ)) divided by its grid maximum w_max = {wMax:G4} mm³"),
                "unitless",
                null));
        foreach (var (maps, prefix, label) in new[] { (sweep.Reference, string.Empty, string.Empty), (sweep.CouplingAware, "coupling_aware_", " (coupling-aware)") })
        {
            if (maps is null)
            {
                continue;
            }

            for (var a = 0; a < 3; a++)
            {
                yield return ($"{prefix}v{axes[a]}.png", new MapContent(maps.Velocity[a], $"V{axes[a]}", $"largest tool speed along {axes[a]}{label}", "mm/s", velocity[a]));
            }

            for (var a = 0; a < 3; a++)
            {
                yield return ($"{prefix}f{axes[a]}.png", new MapContent(maps.Force[a], $"F{axes[a]}", $"largest holding force along {axes[a]}{label}", "N", force[a]));
            }
        }
    }

    private static string Subtitle(AnalysisReport report, string file)
    {
        var robot = report.Robot;
        var spec = report.Sweep.Specification;
        const double deg = 180.0 / Math.PI;
        var fixedText = string.Join(", ", Enumerable.Range(0, robot.JointCount)
            .Where(j => j != spec.XJoint && j != spec.YJoint)
            .Select(j => string.Create(CultureInfo.InvariantCulture, $"{robot.Joints[j].Name} = {spec.FixedRad[j] * deg:0.##}")));
        var method = file.StartsWith("coupling_aware_", StringComparison.Ordinal)
            ? "coupling-aware limits"
            : file.StartsWith("manipulability", StringComparison.Ordinal) ? "position Jacobian of the used joints" : "reference method: independent per-joint limits";
        return string.Create(
            CultureInfo.InvariantCulture,
            $"sweep {robot.Joints[spec.XJoint].Name} {spec.XMinRad * deg:0.##}..{spec.XAt(spec.XCount - 1) * deg:0.##} deg x {robot.Joints[spec.YJoint].Name} " +
            $"{spec.YMinRad * deg:0.##}..{spec.YAt(spec.YCount - 1) * deg:0.##} deg, step {spec.StepRad * deg:0.##} deg; fixed (deg): {fixedText}; {method}");
    }
}
