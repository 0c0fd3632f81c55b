using RobotControl.Definitions.Json;
using System.Text.Json;
using RobotControl.Definitions.Model;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Sdk.Testing;

/// <summary>Creates <see cref="PluginHarness{TPlugin}"/>s and reads settings the way graph files give them.</summary>
public static class PluginHarness
{
    /// <summary>
    /// Creates the plug-in through <paramref name="create"/> with a context like the host's: instance name
    /// <paramref name="instanceName"/>, robot <paramref name="robot"/>, a <see cref="ManualClock"/>, the current
    /// directory as base directory; ticks at <paramref name="rateHz"/>.
    /// </summary>
    /// <exception cref="SettingsException">The plug-in rejected its settings.</exception>
    public static PluginHarness<TPlugin> Create<TPlugin>(Func<PluginContext, TPlugin> create, double rateHz = 1000, RobotDefinition? robot = null, string instanceName = "under_test")
        where TPlugin : Plugin
    {
        ArgumentNullException.ThrowIfNull(create);
        ArgumentOutOfRangeException.ThrowIfNegativeOrZero(rateHz);
        if (!double.IsFinite(rateHz))
        {
            throw new ArgumentOutOfRangeException(nameof(rateHz), "the loop rate must be finite");
        }

        var clock = new ManualClock();
        var plugin = create(new PluginContext(instanceName, robot, clock, Directory.GetCurrentDirectory()));
        return new PluginHarness<TPlugin>(plugin, clock, TimeSpan.FromTicks((long)Math.Round(TimeSpan.TicksPerSecond / rateHz)));
    }

    /// <summary>
    /// Reads settings from the JSON object a graph file would hold for the instance (snake_case names, defaults for
    /// missing ones), checked exactly as the host checks them.
    /// </summary>
    /// <exception cref="SettingsException">Unknown names, wrong types or out-of-range values (every problem).</exception>
    public static TSettings ReadSettings<TSettings>(string json)
        where TSettings : PluginSettings, new()
    {
        ArgumentNullException.ThrowIfNull(json);
        using var document = JsonDocument.Parse(json);
        var errors = new List<JsonProblem>();
        var settings = SettingsSchema.For(typeof(TSettings)).Read(document.RootElement, errors);
        return settings is TSettings typed && errors.Count == 0 ? typed : throw new SettingsException(typeof(TSettings).Name, errors);
    }
}
