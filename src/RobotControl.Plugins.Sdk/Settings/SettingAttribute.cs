namespace RobotControl.Plugins.Sdk.Settings;

/// <summary>Describes one setting for validation and for a generic settings pane.</summary>
/// <param name="description">What the setting does (shown as the field's help).</param>
[AttributeUsage(AttributeTargets.Property, AllowMultiple = false, Inherited = true)]
public sealed class SettingAttribute(string description) : Attribute
{
    /// <summary>What the setting does.</summary>
    public string Description { get; } = description;

    /// <summary>Units shown next to the field, e.g. <c>mm</c>, <c>deg</c>, <c>N/mm</c>.</summary>
    public string Units { get; init; } = "";

    /// <summary>Smallest allowed value of a numeric setting (NaN: unbounded).</summary>
    public double Minimum { get; init; } = double.NaN;

    /// <summary>Largest allowed value of a numeric setting (NaN: unbounded).</summary>
    public double Maximum { get; init; } = double.NaN;

    /// <summary>True for a string that names a file (a GUI offers a file picker; relative to the graph file).</summary>
    public bool IsFilePath { get; init; }

    /// <summary>True when an empty string is not allowed.</summary>
    public bool Required { get; init; }
}
