using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Sdk;

/// <summary>
/// A plug-in with typed settings. The host finds the settings type from the generic argument, builds and validates it
/// from the graph file, and passes it to the constructor <c>(TSettings settings, PluginContext context)</c>.
/// </summary>
/// <typeparam name="TSettings">The settings record (properties described with <see cref="SettingAttribute"/>).</typeparam>
public abstract class Plugin<TSettings> : Plugin
    where TSettings : PluginSettings, new()
{
    /// <summary>Validates <paramref name="settings"/> and keeps them.</summary>
    /// <exception cref="SettingsException">A setting is out of range or inconsistent.</exception>
    protected Plugin(TSettings settings, PluginContext context)
        : base(context)
    {
        ArgumentNullException.ThrowIfNull(settings);
        SettingsSchema.For(typeof(TSettings)).ThrowIfInvalid(settings, context.InstanceName);
        Settings = settings;
    }

    /// <summary>The instance's settings (immutable).</summary>
    public TSettings Settings { get; }

    /// <inheritdoc />
    public override PluginSettings SettingsObject => Settings;
}
