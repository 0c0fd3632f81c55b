using RobotControl.Plugins.Sdk.Settings;
using RobotControl.Plugins.Sdk.Testing;

namespace MyLab.Filters.Tests;

public sealed class LowPassPluginTests
{
    [Fact]
    public void A_step_reaches_63_percent_after_one_time_constant()
    {
        // 1 kHz loop, 5 Hz cut-off: tau = 1 / (2 pi 5) s, about 31.8 ticks.
        using var harness = PluginHarness.Create(context => new LowPassPlugin(new LowPassSettings { CutoffHz = 5 }, context));
        harness.Set("in", 0).Tick();
        harness.Set("in", 10).Run(TimeSpan.FromSeconds(1 / (2 * Math.PI * 5)));

        Assert.InRange(harness["out"], 6.2, 6.4);
    }

    [Fact]
    public void The_first_tick_passes_the_input_through()
    {
        using var harness = PluginHarness.Create(context => new LowPassPlugin(new LowPassSettings(), context));
        harness.Set("in", 108.97).Tick();

        Assert.Equal(108.97, harness["out"]);
    }

    [Fact]
    public void Settings_read_as_a_graph_file_gives_them_and_out_of_range_cutoffs_are_refused()
    {
        Assert.Equal(2, PluginHarness.ReadSettings<LowPassSettings>("""{ "cutoff_hz": 2 }""").CutoffHz);
        var error = Assert.Throws<SettingsException>(() => PluginHarness.ReadSettings<LowPassSettings>("""{ "cutoff_hz": 1000 }"""));
        Assert.Equal("cutoff_hz", Assert.Single(error.Errors).Path);
    }
}
