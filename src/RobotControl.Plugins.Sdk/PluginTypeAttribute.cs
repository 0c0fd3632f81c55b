namespace RobotControl.Plugins.Sdk;

/// <summary>
/// Marks a <see cref="Plugin"/> class as a plug-in type and gives the name graph files use for it. Types without the
/// attribute are not discovered.
/// </summary>
/// <param name="name">The type name in graph files, e.g. <c>clutch</c>; letters, digits, <c>_</c> and <c>-</c>.</param>
[AttributeUsage(AttributeTargets.Class, AllowMultiple = false, Inherited = false)]
public sealed class PluginTypeAttribute(string name) : Attribute
{
    /// <summary>The type name in graph files.</summary>
    public string Name { get; } = name;

    /// <summary>One-line description for catalogues and the GUI.</summary>
    public string Description { get; init; } = "";
}
