using RobotControl.Host.Harness;
using RobotControl.Host.Realtime;
using RobotControl.Host.Station;
using RobotControl.Plugins.Standard.Conditioning;
using RobotControl.Runtime.Discovery;

namespace RobotControl.Host.Tests.Station;

/// <summary>A graph that names no robot, run as a station: its loop alone on the wall clock.</summary>
public sealed class StationRunTests
{
    private static PluginCatalog Catalog() => PluginCatalog.FromAssemblies(typeof(ClutchPlugin).Assembly);

    private static string Graph()
    {
        var path = Path.Combine(Directory.CreateTempSubdirectory("rcst").FullName, "station.json");
        File.WriteAllText(path, """
            { "schema": "robotcontrol/graph/1", "loop_rate_hz": 1000,
              "instances": [ { "name": "clutch", "type": "clutch", "settings": {} } ], "wires": [] }
            """);
        return path;
    }

    [Fact]
    public void A_station_pinned_to_a_cpu_starts_its_loop_thread_alone_and_reports_its_ticks_and_every_output()
    {
        // A CPU given: the loop thread applies its scheduling in its prologue; with no bus thread to wait for, the start
        // does not wait out its 5 s for a second prologue that never comes.
        var report = StationRun.Run(new RunOptions { GraphPath = Graph(), Virtual = false, Duration = TimeSpan.FromMilliseconds(300), Threads = new RealtimeThreads(0, 0) }, Catalog());

        Assert.True(report.Ticks > 0, $"{report.Ticks} ticks");
        Assert.True(report.LoopStopped);
        Assert.False(report.Interrupted);
        Assert.Contains("CPU 0", report.Scheduling, StringComparison.Ordinal);
        Assert.Contains("clutch.x", report.Signals.Keys);
        Assert.Empty(report.PluginFaults);
        Assert.Contains("\"kind\": \"station\"", report.ToJson(), StringComparison.Ordinal);
    }

    [Fact]
    public void Options_that_need_a_robot_are_refused_in_one_line_naming_the_file()
    {
        var graph = Graph();
        var error = Assert.Throws<InvalidOperationException>(() => StationRun.Run(new RunOptions { GraphPath = graph, Virtual = false, Transport = "serial:/dev/ttyUSB0" }, Catalog()));
        Assert.Equal($"{graph}: the graph names no robot file: --transport opens the robot's bus; a station without a robot has none", error.Message);
    }
}
