using System.Text.Json.Nodes;

namespace RobotControl.Cli.Tests.Commands.Run;

/// <summary><c>robotctl run</c> and <c>fk</c> refuse bad input before anything starts, in one line (issue 18, classes 3, 4, 5, 8).</summary>
public sealed class RunCommandHardeningTests : IDisposable
{
    private readonly string _root = Path.Combine(Path.GetTempPath(), $"rc-run-cli-{Guid.NewGuid():N}");

    public RunCommandHardeningTests() => Directory.CreateDirectory(_root);

    private static string Graph => Cli.RepoFile("graphs/teleop-lb.json");

    [Theory]
    [InlineData("9999999999999s")]
    [InlineData("-1s")]
    [InlineData("NaN")]
    [InlineData("2d")]
    public void A_nonsense_duration_is_refused_while_parsing(string duration) =>
        Cli.AssertRefused(Cli.Run("run", Graph, "--virtual", "--duration", duration), "--duration");

    [Fact]
    public void An_injected_reset_after_the_end_of_the_run_is_refused_before_it_starts()
    {
        var result = Cli.Run("run", Graph, "--virtual", "--duration", "1s", "--inject", "reset=right.shoulder@1e9s");

        Cli.AssertRefused(result, "after the end of the run (1 s)");
        Assert.Equal(string.Empty, result.Output);
    }

    [Theory]
    [InlineData("stale=ik_right@0.5s", "--inject 'stale=ik_right@0.5s': plug-in 'ik_right' cannot take stale faults (plug-ins that take them: touch_right, touch_left)")]
    [InlineData("jump=pedals:5mm@0.5s", "--inject 'jump=pedals:5mm@0.5s': no plug-in 'pedals' in the graph (plug-ins that take jump faults: touch_right, touch_left)")]
    public void A_device_fault_aimed_at_an_instance_that_cannot_take_it_is_refused_before_it_starts(string inject, string message)
    {
        var result = Cli.Run("run", Graph, "--virtual", "--duration", "1s", "--inject", inject);

        Cli.AssertRefused(result, message);
        Assert.Equal(2, result.Code);
        Assert.Equal(string.Empty, result.Output);
    }

    [Theory]
    [InlineData("missing-dir/report.json", "does not exist")]
    [InlineData("", "is a directory")]
    [InlineData("/dev/full", "not a regular file")]
    [InlineData("/proc/robotctl-report.json", "cannot write in /proc")]
    public void An_unwritable_report_is_refused_before_the_run(string report, string expected)
    {
        var path = report.StartsWith('/') ? report : Path.Combine(_root, report);

        var result = Cli.Run("run", Graph, "--virtual", "--duration", "10ms", "--report", path);

        Cli.AssertRefused(result, "--report");
        Assert.Contains(expected, result.Error, StringComparison.Ordinal);
        Assert.Equal(string.Empty, result.Output);
    }

    [Theory]
    [InlineData("")]
    [InlineData("   ")]
    public void An_empty_report_path_is_one_line_naming_the_option(string report)
    {
        var result = Cli.Run("run", Graph, "--virtual", "--duration", "10ms", "--report", report);

        Cli.AssertRefused(result, "--report: the path is empty");
        Assert.Equal(string.Empty, result.Output);
    }

    [Fact]
    public void A_stall_is_counted_in_the_summary_beside_the_deadline_misses_and_says_what_each_counts()
    {
        // Ticks take no loop time (--tick-cost free): the stall is the run's only delay, whatever the machine's load.
        var (code, output, error) = Cli.Run("run", Graph, "--virtual", "--tick-cost", "free", "--duration", "1500ms", "--inject", "stall=600ms@1s", "--continue-on-fault");

        Assert.True(code is 0 or 1, error);
        Assert.Contains("virtual clock, ticks take no loop time", output, StringComparison.Ordinal);
        Assert.Matches(@"summary: 1500 ticks in [\d.]+ s of loop time, 0 deadline misses \(ticks started late\); 1 silence trip\(s\), longest 60\d\.\d ms \(host_stall\)", output);
    }

    [Fact]
    public void Free_ticks_on_a_real_time_run_are_one_line_naming_the_option()
    {
        var result = Cli.Run("run", Graph, "--transport", "serial:/dev/null", "--tick-cost", "free", "--duration", "10ms");

        Cli.AssertRefused(result, "--tick-cost free applies to --virtual runs");
    }

    [Fact]
    public void The_report_is_written_whole_under_its_name_and_nothing_else_is_left()
    {
        var report = Path.Combine(_root, "report.json");

        var (code, output, error) = Cli.Run("run", Graph, "--virtual", "--duration", "20ms", "--report", report);

        Assert.True(code is 0 or 1, error);
        Assert.Contains("report: ", output, StringComparison.Ordinal);
        Assert.NotNull(JsonNode.Parse(File.ReadAllText(report))!["ticks"]);
        Assert.Equal([report], Directory.GetFileSystemEntries(_root));
    }

    [Fact]
    public void A_graph_whose_robot_file_has_no_modules_section_fails_clearly()
    {
        var robot = Cli.CopyRobot(_root, r => r.Remove("modules"));
        var graph = CopyGraph(robot, "virtual");

        Cli.AssertRefused(Cli.Run("run", graph, "--virtual", "--duration", "10ms"), "has no modules section");
    }

    [Fact]
    public void The_graphs_transport_is_checked_with_virtual_too()
    {
        var graph = CopyGraph(Cli.RepoFile("hardware/robots/lb-1.0.json"), "serial:/dev/ttyUSB0?baud=fast");

        Cli.AssertRefused(Cli.Run("run", graph, "--virtual", "--duration", "10ms"), "$.transport: transport 'serial:/dev/ttyUSB0?baud=fast': baud 'fast'");
    }

    [Fact]
    public void An_implausible_length_in_the_robot_file_is_refused_by_the_loader_and_fk_prints_nothing()
    {
        var robot = Cli.CopyRobot(_root, r => r["dh"]!.AsArray()[1]!["d_mm"] = 1e300);

        var result = Cli.Run("fk", robot);

        Assert.NotEqual(0, result.Code);
        Assert.Contains("d_mm", result.Error, StringComparison.Ordinal);
        Assert.Equal(string.Empty, result.Output);
    }

    public void Dispose() => Directory.Delete(_root, recursive: true);

    private string CopyGraph(string robot, string transport)
    {
        var source = Graph;
        var json = JsonNode.Parse(File.ReadAllText(source))!.AsObject();
        json["robot"] = robot;
        json["transport"] = transport;
        foreach (var instance in json["instances"]!.AsArray())
        {
            if (instance!["settings"]?["script"] is JsonValue script)
            {
                instance["settings"]!["script"] = Path.Combine(Path.GetDirectoryName(source)!, script.GetValue<string>());
            }
        }

        var path = Path.Combine(_root, "graph.json");
        File.WriteAllText(path, json.ToJsonString());
        return path;
    }
}
