using RobotControl.Analysis.Output;
using RobotControl.Analysis.Tests.Plotting;

namespace RobotControl.Analysis.Tests.Output;

public sealed class AnalysisOutputWriterTests : IDisposable
{
    private readonly string _root = Path.Combine(Path.GetTempPath(), $"rc-analysis-test-{Guid.NewGuid():N}");

    [Fact]
    public void Writes_summary_csv_and_non_trivial_maps()
    {
        var robot = TestRobots.Lb;
        var report = CapabilityAnalyzer.Run(robot, new AnalysisOptions { Workspace = false, CouplingAware = true });
        var dir = Path.Combine(_root, "out");

        var files = AnalysisOutputWriter.Write(report, dir);

        Assert.Contains(Path.Combine(dir, "summary.json"), files);
        var csv = File.ReadAllLines(Path.Combine(dir, "sweep.csv"));
        Assert.Equal(report.Sweep.Count + 1, csv.Length);
        var header = csv[0].Split(',');
        Assert.Contains("fz_N", header);
        Assert.Contains("ca_fz_N", header);
        Assert.All(csv.Skip(1).Take(50), row => Assert.Equal(header.Length, row.Split(',').Length));

        foreach (var name in AnalysisOutputWriter.MapFiles.Concat(["coupling_aware_fx.png"]))
        {
            var bytes = File.ReadAllBytes(Path.Combine(dir, name));
            var image = DecodedPng.Decode(bytes);
            Assert.True(bytes.Length > 10_000, $"{name} is only {bytes.Length} bytes");
            Assert.Equal(960, image.Width);
            Assert.Equal(780, image.Height);
            var colours = image.DistinctColours();
            Assert.True(colours > 100, $"{name} has only {colours} colours");
        }

        Assert.Empty(Directory.GetDirectories(_root, ".*partial*"));
    }

    [Fact]
    public void Summary_lists_every_drive_in_file_order_and_the_requirements()
    {
        var robot = TestRobots.Crb;
        var report = CapabilityAnalyzer.Run(robot, new AnalysisOptions { Workspace = false });

        using var json = System.Text.Json.JsonDocument.Parse(SummaryJsonWriter.Write(report));
        var root = json.RootElement;

        Assert.Equal("CRB-1.0", root.GetProperty("robot").GetString());
        Assert.Equal(
            ["shoulder_yaw", "shoulder_pitch", "elbow", "tool_roll", "tool_open_close"],
            root.GetProperty("drivetrain").EnumerateArray().Select(d => d.GetProperty("joint").GetString()));
        var sweep = root.GetProperty("sweep");
        Assert.Equal(136 * 106, sweep.GetProperty("points").GetInt32());
        Assert.Equal(3, sweep.GetProperty("force_N").GetProperty("mean").GetArrayLength());
        var fraction = sweep.GetProperty("requirements").GetProperty("force_N").GetProperty("z").GetProperty("fraction_met").GetDouble();
        Assert.InRange(fraction, 0, 1);
        Assert.False(root.TryGetProperty("coupling_aware", out _));
    }

    public void Dispose()
    {
        if (Directory.Exists(_root))
        {
            Directory.Delete(_root, recursive: true);
        }
    }
}
