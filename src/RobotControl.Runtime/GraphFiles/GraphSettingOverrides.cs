using RobotControl.Definitions.Json;
using System.Globalization;
using System.Text.Json;
using System.Text.Json.Nodes;
using RobotControl.Plugins.Sdk.Settings;
using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.Graph;

namespace RobotControl.Runtime.GraphFiles;

/// <summary>
/// Applies <c>--set</c> overrides to a graph file's JSON before it is loaded, so an overridden value is checked by the
/// same loader, with the same messages and JSON paths, as a value written in the file. A value is written as a JSON
/// number or boolean when the setting is of that kind and the text reads as one, otherwise as a string (which the
/// loader then reports as the wrong type). An override naming no instance of the file is a problem of its own,
/// reported together with the loader's (<see cref="GraphFile.Load(string, PluginCatalog, TimeProvider, IReadOnlyList{SettingOverride})"/>).
/// </summary>
public static class GraphSettingOverrides
{
    private static readonly JsonDocumentOptions DocumentOptions = new() { CommentHandling = JsonCommentHandling.Skip };

    /// <summary>
    /// The graph JSON with <paramref name="overrides"/> applied (the text unchanged when there are none); an override
    /// that names no instance is added to <paramref name="problems"/> and not applied. Each applied override is put in
    /// <paramref name="written"/> (when given) under the JSON path it wrote, so that the loader's problems there can
    /// name it (<see cref="NameOverrides"/>).
    /// </summary>
    /// <exception cref="GraphException">The JSON is not a graph with an instances array.</exception>
    public static string Apply(string json, IReadOnlyList<SettingOverride> overrides, PluginCatalog catalog, string path, ICollection<JsonProblem> problems, IDictionary<string, SettingOverride>? written = null)
    {
        ArgumentNullException.ThrowIfNull(json);
        ArgumentNullException.ThrowIfNull(overrides);
        ArgumentNullException.ThrowIfNull(catalog);
        ArgumentNullException.ThrowIfNull(problems);
        if (overrides.Count == 0)
        {
            return json;
        }

        JsonNode? root;
        try
        {
            root = JsonNode.Parse(json, documentOptions: DocumentOptions);
        }
        catch (JsonException ex)
        {
            throw new GraphException([new JsonProblem("$", $"not valid JSON: {ex.Message}")], path);
        }

        if (root is not JsonObject graph || graph["instances"] is not JsonArray instances)
        {
            throw new GraphException([new JsonProblem("$.instances", "the graph has no instances array to apply --set to")], path);
        }

        foreach (var item in overrides)
        {
            var instance = instances.OfType<JsonObject>().FirstOrDefault(i => i["name"] is JsonValue v && v.TryGetValue<string>(out var n) && n == item.Instance);
            if (instance is null)
            {
                var names = instances.OfType<JsonObject>().Select(i => i["name"]?.ToString()).Where(n => n is not null);
                problems.Add(new JsonProblem($"--set {item}", $"no instance named '{item.Instance}' (instances: {string.Join(", ", names)})"));
                continue;
            }

            if (instance["settings"] is not JsonObject settings)
            {
                settings = [];
                instance["settings"] = settings;
            }

            if (Value(item, instance, catalog) is not { } value)
            {
                problems.Add(new JsonProblem($"--set {item}", $"'{item.Value.Trim()}' is not a finite number"));
                continue;
            }

            settings[item.Setting] = value;
            if (written is not null)
            {
                written[string.Create(CultureInfo.InvariantCulture, $"$.instances[{instances.IndexOf(instance)}].settings.{item.Setting}")] = item;
            }
        }

        return root.ToJsonString();
    }

    /// <summary>
    /// <paramref name="problems"/> with each one at (or inside) a path an override wrote named by that override
    /// (<c>--set scaling.ratio=abc: $.instances[2].settings.ratio: expected a number, found string</c>): the user typed
    /// the value on the command line, not in the file.
    /// </summary>
    public static IReadOnlyList<JsonProblem> NameOverrides(IReadOnlyList<JsonProblem> problems, IReadOnlyDictionary<string, SettingOverride> written)
    {
        ArgumentNullException.ThrowIfNull(problems);
        ArgumentNullException.ThrowIfNull(written);
        return [.. problems.Select(p => Writer(p.Path, written) is { } item ? new JsonProblem($"--set {item}", $"{p.Path}: {p.Message}") : p)];
    }

    private static SettingOverride? Writer(string path, IReadOnlyDictionary<string, SettingOverride> written) =>
        written.FirstOrDefault(w => path == w.Key || path.StartsWith(w.Key + ".", StringComparison.Ordinal) || path.StartsWith(w.Key + "[", StringComparison.Ordinal)).Value;

    /// <summary>The override's JSON value, or null for a number setting given a non-finite number (NaN, Infinity), which JSON cannot hold.</summary>
    private static JsonValue? Value(SettingOverride item, JsonObject instance, PluginCatalog catalog)
    {
        var type = instance["type"] is JsonValue t && t.TryGetValue<string>(out var name) ? catalog.Find(name) : null;
        var kind = type?.Settings?.Find(item.Setting)?.Kind;
        var text = item.Value.Trim();
        return kind switch
        {
            SettingKind.Number when double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out var d) => double.IsFinite(d) ? JsonValue.Create(d) : null,
            SettingKind.Integer when long.TryParse(text, NumberStyles.Integer, CultureInfo.InvariantCulture, out var i) => JsonValue.Create(i),
            SettingKind.Boolean when bool.TryParse(text, out var b) => JsonValue.Create(b),
            _ => JsonValue.Create(item.Value),
        };
    }
}
