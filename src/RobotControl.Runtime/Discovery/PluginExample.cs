using System.Text.Json;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Runtime.Discovery;

/// <summary>
/// Settings of one instance in a graph file, to describe a type whose ports cannot be made from its defaults (e.g. a
/// simulated Touch needs its hand script): its ports are those an instance with these settings declares.
/// </summary>
/// <param name="Settings">The instance's settings, read and checked by the type's schema.</param>
/// <param name="Instance">The instance's name in the graph.</param>
/// <param name="GraphFile">The graph file's name (without its folder).</param>
/// <param name="BaseDirectory">The graph's folder: file paths in the settings are relative to it.</param>
public sealed record PluginExample(PluginSettings? Settings, string Instance, string GraphFile, string BaseDirectory)
{
    /// <summary>
    /// The first instance of each type of <paramref name="catalog"/> in the graph file <paramref name="graphPath"/>
    /// whose settings read without a problem, by type name.
    /// </summary>
    /// <exception cref="IOException">The file cannot be read.</exception>
    /// <exception cref="JsonException">The file is not JSON.</exception>
    public static Dictionary<string, PluginExample> FromGraph(string graphPath, PluginCatalog catalog)
    {
        ArgumentNullException.ThrowIfNull(graphPath);
        ArgumentNullException.ThrowIfNull(catalog);
        using var document = JsonDocument.Parse(File.ReadAllText(graphPath));
        var folder = Path.GetDirectoryName(Path.GetFullPath(graphPath))!;
        var examples = new Dictionary<string, PluginExample>(StringComparer.Ordinal);
        foreach (var (name, type, settings) in GraphInstances.Read(document.RootElement, catalog))
        {
            examples.TryAdd(type.Name, new PluginExample(settings, name, Path.GetFileName(graphPath), folder));
        }

        return examples;
    }
}
