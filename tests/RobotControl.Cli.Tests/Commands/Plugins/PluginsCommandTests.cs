using System.Text.Json;
using RobotControl.Cli.Commands.Plugins;
using RobotControl.Plugins.Sdk;

namespace RobotControl.Cli.Tests.Commands.Plugins;

public sealed class PluginsCommandTests
{
    [Fact]
    public void Json_lists_ports_with_units_settings_with_ranges_and_versions()
    {
        var output = new StringWriter();
        var error = new StringWriter();
        Assert.Equal(0, PluginsCommand.Run(null, null, PluginsFormat.Json, output, error));
        Assert.Equal(string.Empty, error.ToString());

        using var doc = JsonDocument.Parse(output.ToString());
        Assert.Equal(SdkVersion.Text, doc.RootElement.GetProperty("host_sdk_version").GetString());
        var clutch = doc.RootElement.GetProperty("plugins").EnumerateArray().Single(p => p.GetProperty("name").GetString() == "clutch");
        Assert.Equal("RobotControl.Plugins.Standard", clutch.GetProperty("assembly").GetString());
        Assert.Equal(SdkVersion.Format(SdkVersion.Current), clutch.GetProperty("sdk_version").GetString());
        var x = clutch.GetProperty("ports").GetProperty("inputs").EnumerateArray().First();
        Assert.Equal(("x", "mm"), (x.GetProperty("name").GetString(), x.GetProperty("units").GetString()));
        Assert.Equal("hold_last_finite", clutch.GetProperty("ports").GetProperty("outputs")[0].GetProperty("safe_value").GetString());
        var threshold = clutch.GetProperty("settings").EnumerateArray().Single(s => s.GetProperty("name").GetString() == "threshold");
        Assert.Equal((-1000.0, 1000.0), (threshold.GetProperty("minimum").GetDouble(), threshold.GetProperty("maximum").GetDouble()));
        Assert.Equal(0.5, threshold.GetProperty("default").GetDouble());
        var inverse = doc.RootElement.GetProperty("plugins").EnumerateArray().Single(p => p.GetProperty("name").GetString() == "inverse_kinematics");
        Assert.False(inverse.TryGetProperty("ports", out _)); // declared per joint: without a robot it cannot be created
        Assert.Contains("no robot", inverse.GetProperty("ports_problem").GetString(), StringComparison.Ordinal);
    }

    [Fact]
    public void Table_shows_each_type_with_its_ports_and_says_why_ports_need_a_robot()
    {
        var output = new StringWriter();
        Assert.Equal(0, PluginsCommand.Run(null, null, PluginsFormat.Table, output, new StringWriter()));
        var text = output.ToString();
        Assert.Contains("clutch  Holds the target", text, StringComparison.Ordinal);
        Assert.Contains("threshold  number     -1000 .. 1000  default 0.5", text, StringComparison.Ordinal);
        // Inverse kinematics declares a port per joint of the graph's robot: without --robot it says so.
        Assert.Matches(@"inverse_kinematics .*\n.*\n  ports     declared when created; with default settings and no robot: .*robot", text);
    }

    [Fact]
    public void The_kept_reference_in_docs_is_what_the_plugins_declare()
    {
        var output = new StringWriter();
        var error = new StringWriter();
        Assert.Equal(0, PluginsCommand.Run(null, Cli.RepoFile("hardware/robots/lb-1.0.json"), Cli.RepoFile("graphs/teleop-lb.json"), PluginsFormat.Markdown, output, error));
        Assert.Equal(string.Empty, error.ToString());

        var kept = File.ReadAllText(Cli.RepoFile("docs/plugin-reference.md")).ReplaceLineEndings("\n");
        Assert.True(
            kept == output.ToString(),
            "docs/plugin-reference.md differs from what the plug-ins declare: regenerate it with the command at its top");
        Assert.Contains("## inverse_kinematics", kept, StringComparison.Ordinal);
        Assert.Contains("| `right.elbow` | rad |", kept, StringComparison.Ordinal); // a port per joint of LB-1.0
        Assert.Contains("Ports of an instance with the settings of touch_right in teleop-lb.json", kept, StringComparison.Ordinal);
    }

    [Fact]
    public void An_examples_file_that_is_not_a_graph_is_one_line_naming_it()
    {
        var (code, output, error) = Cli.Run("plugins", "--markdown", "--examples", Cli.RepoFile("README.md"));
        Assert.Equal(2, code);
        Assert.StartsWith($"--examples: {Cli.RepoFile("README.md")}: ", error, StringComparison.Ordinal);
        Assert.Single(error.TrimEnd().Split('\n'));
        Assert.Equal(string.Empty, output);
    }

    [Fact]
    public void Json_and_markdown_together_are_refused_in_one_line()
    {
        var (code, output, error) = Cli.Run("plugins", "--json", "--markdown");
        Assert.Equal(2, code);
        Assert.Equal("--json and --markdown: give one of them" + Environment.NewLine, error);
        Assert.Equal(string.Empty, output);
    }

    [Fact]
    public void A_missing_plugins_folder_is_one_line_naming_it()
    {
        var error = new StringWriter();
        Assert.Equal(2, PluginsCommand.Run("/nonexistent/plugins", null, PluginsFormat.Table, new StringWriter(), error));
        Assert.Equal("--plugins: folder '/nonexistent/plugins' does not exist" + Environment.NewLine, error.ToString());
    }
}
