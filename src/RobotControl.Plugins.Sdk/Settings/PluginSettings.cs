using RobotControl.Definitions.Json;

namespace RobotControl.Plugins.Sdk.Settings;

/// <summary>
/// Base of every plug-in's settings: an immutable record whose public <c>init</c> properties are the settings, each
/// described by a <see cref="SettingAttribute"/> (description, units, range) so a GUI can build the settings pane and
/// the host can read, validate and write them (JSON names are the snake_case property names) without plug-in code.
/// </summary>
public abstract record PluginSettings
{
    /// <summary>
    /// Checks rules that span several settings (single-setting ranges are checked from the attributes). Return one
    /// problem per finding, its path the setting's JSON name.
    /// </summary>
    public virtual IEnumerable<JsonProblem> CheckConsistency() => [];
}
