using System.Reflection;

namespace RobotControl.Plugins.Sdk.Settings;

/// <summary>What a GUI or the graph-file reader needs to know about one setting.</summary>
/// <param name="JsonName">Name in graph files (snake_case of the property name).</param>
/// <param name="Property">The settings property.</param>
/// <param name="Kind">Value kind.</param>
/// <param name="Description">Help text.</param>
/// <param name="Units">Units, or empty.</param>
/// <param name="Minimum">Smallest value of a numeric setting (NaN: unbounded).</param>
/// <param name="Maximum">Largest value of a numeric setting (NaN: unbounded).</param>
/// <param name="IsFilePath">A string naming a file.</param>
/// <param name="Required">An empty string is not allowed.</param>
/// <param name="DefaultValue">The value a freshly constructed settings object holds.</param>
/// <param name="EnumNames">Allowed names of an enum setting (snake_case), otherwise empty.</param>
public sealed record SettingDescriptor(
    string JsonName,
    PropertyInfo Property,
    SettingKind Kind,
    string Description,
    string Units,
    double Minimum,
    double Maximum,
    bool IsFilePath,
    bool Required,
    object? DefaultValue,
    IReadOnlyList<string> EnumNames)
{
    /// <summary>
    /// True when <paramref name="value"/> is finite and inside <see cref="Minimum"/>..<see cref="Maximum"/> (a NaN
    /// bound is no bound): what a graph file's value must be, and what an input that takes this setting's values at
    /// run time (a scaling ratio, for example) accepts.
    /// </summary>
    public bool Accepts(double value) => double.IsFinite(value) && !(value < Minimum) && !(value > Maximum);
}

/// <summary>Value kinds a setting may have.</summary>
public enum SettingKind
{
    /// <summary>A finite double.</summary>
    Number,

    /// <summary>A 32-bit integer.</summary>
    Integer,

    /// <summary>true / false.</summary>
    Boolean,

    /// <summary>Text (or a file path).</summary>
    Text,

    /// <summary>One name of an enum (snake_case in files).</summary>
    Choice,
}
