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
    /// error per problem, named by the setting's JSON name.
    /// </summary>
    public virtual IEnumerable<SettingError> CheckConsistency() => [];
}

/// <summary>A settings problem.</summary>
/// <param name="Setting">The setting's JSON name (or empty for the whole object).</param>
/// <param name="Message">What is wrong.</param>
public sealed record SettingError(string Setting, string Message);
