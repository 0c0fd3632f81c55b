using System.Text.Json;
using RobotControl.Definitions.Json;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Runtime.Discovery;

/// <summary>
/// The instances of a graph file's text, read leniently: each one with a name, a type the catalog knows and settings
/// that read without a problem, in file order. Anything else is skipped, for the graph loader to report.
/// </summary>
public static class GraphInstances
{
    /// <summary>The instances of <paramref name="root"/> (a graph document) that <paramref name="catalog"/> can describe.</summary>
    public static IEnumerable<(string Name, PluginTypeInfo Type, PluginSettings? Settings)> Read(JsonElement root, PluginCatalog catalog)
    {
        ArgumentNullException.ThrowIfNull(catalog);
        if (root.ValueKind != JsonValueKind.Object || !root.TryGetProperty("instances", out var instances) || instances.ValueKind != JsonValueKind.Array)
        {
            yield break;
        }

        foreach (var item in instances.EnumerateArray())
        {
            if (item.ValueKind != JsonValueKind.Object || !item.TryGetProperty("name", out var name) || name.ValueKind != JsonValueKind.String
                || !item.TryGetProperty("type", out var type) || type.ValueKind != JsonValueKind.String || catalog.Find(type.GetString()!) is not { } info)
            {
                continue;
            }

            var errors = new List<JsonProblem>();
            var settings = info.Settings?.Read(item.TryGetProperty("settings", out var s) ? s : default, errors);
            if (errors.Count == 0)
            {
                yield return (name.GetString()!, info, settings);
            }
        }
    }
}
