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
        Assert.Equal(0, PluginsCommand.Run(null, null, json: true, output, error));
        Assert.Equal(string.Empty, error.ToString());

        using var doc = JsonDocument.Parse(output.ToString());
        Assert.Equal(SdkVersion.Text, doc.RootElement.GetProperty("host_sdk_version").GetString());
        var clutch = doc.RootElement.GetProperty("plugins").EnumerateArray().Single(p => p.GetProperty("name").GetString() == "clutch");
        Assert.Equal("RobotControl.Plugins.Standard", clutch.GetProperty("assembly").GetString());
        Assert.Equal(SdkVersion.Format(SdkVersion.Current), clutch.GetProperty("sdk_version").GetString());
        var x = clutch.GetProperty("inputs").EnumerateArray().First();
        Assert.Equal(("x", "mm"), (x.GetProperty("name").GetString(), x.GetProperty("units").GetString()));
        Assert.Equal("hold_last_finite", clutch.GetProperty("outputs")[0].GetProperty("safe_value").GetString());
        var threshold = clutch.GetProperty("settings").EnumerateArray().Single(s => s.GetProperty("name").GetString() == "threshold");
        Assert.Equal((-1000.0, 1000.0), (threshold.GetProperty("minimum").GetDouble(), threshold.GetProperty("maximum").GetDouble()));
        Assert.Equal("0.5", threshold.GetProperty("default").GetString());
    }

    [Fact]
    public void Table_shows_each_type_with_its_ports_and_says_why_ports_need_a_robot()
    {
        var output = new StringWriter();
        Assert.Equal(0, PluginsCommand.Run(null, null, json: false, output, new StringWriter()));
        var text = output.ToString();
        Assert.Contains("clutch  Holds the target", text, StringComparison.Ordinal);
        Assert.Contains("threshold  number     -1000 .. 1000  default 0.5", text, StringComparison.Ordinal);
        // Inverse kinematics declares a port per joint of the graph's robot: without --robot it says so.
        Assert.Matches(@"inverse_kinematics .*\n.*\n  ports     declared when created; with default settings and no robot: .*robot", text);
    }

    [Fact]
    public void A_missing_plugins_folder_is_one_line_naming_it()
    {
        var error = new StringWriter();
        Assert.Equal(2, PluginsCommand.Run("/nonexistent/plugins", null, json: false, new StringWriter(), error));
        Assert.Equal("--plugins: folder '/nonexistent/plugins' does not exist" + Environment.NewLine, error.ToString());
    }
}
