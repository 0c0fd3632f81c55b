using RobotControl.Host.Session;
using RobotControl.Plugins.Standard.Conditioning;
using RobotControl.Plugins.Touch;
using RobotControl.Runtime.Discovery;
using RobotControl.Host.Harness;

namespace RobotControl.Host.Tests.Harness;

public sealed class HeadlessRunTests
{
    private static PluginCatalog Catalog() => PluginCatalog.FromAssemblies(typeof(ClutchPlugin).Assembly, typeof(TouchPlugin).Assembly);

    [Theory]
    [InlineData("teleop-lb.json")]
    [InlineData("teleop-crb.json")]
    public void The_teleoperation_demo_tracks_on_the_virtual_robot(string graph)
    {
        // 8 s covers the circle (60 mm/s at the tool), a clutch press and most of the figure-eight (up to 70 mm/s).
        // Ticks take no loop time, so the run is the same on a loaded machine; the graph's speed is the benchmarks'.
        var report = HeadlessRun.Run(new RunOptions { GraphPath = Graphs.Path(graph), Duration = TimeSpan.FromSeconds(8), TickCost = VirtualTickCost.Free }, Catalog());

        Assert.Equal(8000, report.Ticks);
        Assert.Empty(report.Faults);
        Assert.InRange(report.TrackingRmsMm, 0.01, 2.0);
        Assert.True(report.TrackingMaxMm < 5.0, $"max tracking error {report.TrackingMaxMm} mm");
        Assert.True(report.Bus.Frames > 8000);
        Assert.Equal(0, report.Bus.CrcErrors);
    }

    [Fact]
    public void The_report_has_the_documented_schema()
    {
        var json = new RunReport(1, 2, 3, 4, 5, 6, 7, 8, new BusReport(9, 10, 11, 12, 13), [new FaultEntry(0.5, "robot", "module 1 reset")]).ToJson();
        using var doc = System.Text.Json.JsonDocument.Parse(json);
        var root = doc.RootElement;

        Assert.Equal(["duration_s", "ticks", "deadline_misses", "tick_us", "tracking_error_mm", "bus", "faults", "interrupted", "stopped_on_fault"], root.EnumerateObject().Select(p => p.Name));
        Assert.Equal(["median", "p99", "max"], root.GetProperty("tick_us").EnumerateObject().Select(p => p.Name));
        Assert.Equal(["rms", "max"], root.GetProperty("tracking_error_mm").EnumerateObject().Select(p => p.Name));
        Assert.Equal(["frames", "crc_errors", "timeouts", "retries", "late_replies"], root.GetProperty("bus").EnumerateObject().Select(p => p.Name));
        Assert.Equal("module 1 reset", root.GetProperty("faults")[0].GetProperty("message").GetString());
    }

    [Fact]
    public void A_real_time_report_says_what_the_threads_compiled_after_they_started()
    {
        var compiled = new CompiledAfterStart(1, TimeSpan.FromMicroseconds(30), 14, TimeSpan.FromMicroseconds(1150));
        var json = new RunReport(1, 2, 3, 4, 5, 6, 7, 8, new BusReport(9, 10, 11, 12, 13), []) { Scheduling = "normal", Compiled = compiled }.ToJson();
        using var doc = System.Text.Json.JsonDocument.Parse(json);
        var root = doc.RootElement.GetProperty("compiled_after_start");

        Assert.Equal(["loop_thread", "bus_thread"], root.EnumerateObject().Select(p => p.Name));
        Assert.Equal(1, root.GetProperty("loop_thread").GetProperty("methods").GetInt64());
        Assert.Equal(0.03, root.GetProperty("loop_thread").GetProperty("ms").GetDouble());
        Assert.Equal(14, root.GetProperty("bus_thread").GetProperty("methods").GetInt64());
        Assert.Equal(1.15, root.GetProperty("bus_thread").GetProperty("ms").GetDouble());
        Assert.Equal("loop thread 1 method (0.03 ms), bus thread 14 methods (1.15 ms)", compiled.Summary);
    }

    [Fact]
    public void Fault_injection_text_is_parsed_and_checked()
    {
        var inject = FaultInjection.Parse("ber=1e-5, reset=right.shoulder@5s,reset=12@750ms");

        Assert.Equal(1e-5, inject.BitErrorRate);
        Assert.Equal([new ModuleReset("right.shoulder", TimeSpan.FromSeconds(5)), new ModuleReset("12", TimeSpan.FromMilliseconds(750))], inject.Resets);
        Assert.Throws<FormatException>(() => FaultInjection.Parse("ber=2"));
        Assert.Throws<FormatException>(() => FaultInjection.Parse("reset=right.shoulder"));
        Assert.Throws<FormatException>(() => FaultInjection.Parse("emp=3"));
    }
}

public sealed class ShippedGraphTests
{
    [Theory]
    [InlineData("teleop-lb.json", 5)]
    [InlineData("teleop-crb.json", 4)]
    [InlineData("teleop-lb-touch.json", 5)]
    public void The_shipped_graphs_load_save_back_identically_and_start_where_the_virtual_robot_rests(string graph, int joints)
    {
        var catalog = PluginCatalog.FromAssemblies(typeof(ClutchPlugin).Assembly, typeof(TouchPlugin).Assembly);
        var loaded = RobotControl.Runtime.GraphFiles.GraphFile.Load(Graphs.Path(graph), catalog, TimeProvider.System);
        var saved = RobotControl.Runtime.GraphFiles.GraphFile.ToJson(loaded.Document);
        var reloaded = RobotControl.Runtime.GraphFiles.GraphFile.LoadFromText(saved, Graphs.Path(graph), catalog, TimeProvider.System);

        Assert.Equal(saved, RobotControl.Runtime.GraphFiles.GraphFile.ToJson(reloaded.Document));
        Assert.Equal(loaded.Document.Instances, reloaded.Document.Instances);
        Assert.Equal(2, loaded.Document.Wires.Count(w => w.To.StartsWith("touch_", StringComparison.Ordinal) && w.Delayed) / 3);
        var initial = HeadlessRun.InitialCommand(loaded);
        Assert.All(initial, q => Assert.Equal(joints, q.Length));
        Assert.Equal(-30 * Math.PI / 180, initial[0][0], 9);
    }
}
