using System.Globalization;
using System.Text;
using System.Text.Json;
using RobotControl.Definitions.Json;
using RobotControl.Definitions.Loading;
using RobotControl.Definitions.Model;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Settings;
using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.Loop;
using RobotControl.Runtime.Robot;

namespace RobotControl.Runtime.GraphFiles;

/// <summary>
/// Reads, checks and writes graph files (<c>robotcontrol/graph/1</c>):
/// <code>
/// { "schema": "robotcontrol/graph/1", "robot": "../hardware/robots/lb-1.0.json", "transport": "virtual",
///   "loop_rate_hz": 1000,
///   "instances": [ { "name": "clutch_right", "type": "clutch", "settings": { ... } } ],
///   "wires": [ { "from": "scaling_right.x", "to": "clutch_right.x" },
///              { "from": "walls_right.fx", "to": "touch_right.force_x", "delayed": true } ],
///   "layout": { "clutch_right": { "x": 420, "y": 80 } } }
/// </code>
/// <c>layout</c> is optional and editor-only (the graph editor's node positions, <see cref="GraphLayout"/>).
/// Loading validates everything (unknown type, unknown or mistyped signal, duplicate name, bad setting, cycle) and
/// reports every problem with its JSON path in one <see cref="GraphException"/>; nothing is half-applied.
/// </summary>
public static class GraphFile
{
    private static readonly JsonDocumentOptions DocumentOptions = new() { CommentHandling = JsonCommentHandling.Skip };
    private static readonly string[] TopLevel = ["schema", "robot", "transport", "loop_rate_hz", "instances", "wires", GraphLayout.Field];

    /// <summary>Loads, builds and compiles the graph in <paramref name="path"/>.</summary>
    /// <exception cref="GraphException">Every problem found, with JSON paths.</exception>
    public static LoadedGraph Load(string path, PluginCatalog catalog, TimeProvider time) => Load(path, catalog, time, []);

    /// <summary>
    /// Loads the graph in <paramref name="path"/> with <paramref name="overrides"/> (<c>--set</c>) applied to its
    /// settings first (<see cref="GraphSettingOverrides"/>), validated as if the file held them.
    /// </summary>
    /// <exception cref="GraphException">Every problem found, with JSON paths.</exception>
    public static LoadedGraph Load(string path, PluginCatalog catalog, TimeProvider time, IReadOnlyList<SettingOverride> overrides)
    {
        ArgumentNullException.ThrowIfNull(overrides);
        ArgumentException.ThrowIfNullOrEmpty(path);
        var fullPath = Path.GetFullPath(path);
        string text;
        try
        {
            text = File.ReadAllText(fullPath);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            throw new GraphException([new JsonProblem("$", $"cannot read the file: {ex.Message}")], fullPath);
        }

        ArgumentNullException.ThrowIfNull(catalog);
        var overrideProblems = new List<JsonProblem>();
        var written = new Dictionary<string, SettingOverride>(StringComparer.Ordinal);
        var overridden = GraphSettingOverrides.Apply(text, overrides, catalog, fullPath, overrideProblems, written);
        LoadedGraph loaded;
        try
        {
            loaded = LoadFromText(overridden, fullPath, catalog, time);
        }
        catch (GraphException ex) when (overrideProblems.Count > 0 || written.Count > 0)
        {
            throw new GraphException([.. overrideProblems, .. GraphSettingOverrides.NameOverrides(ex.Problems, written)], fullPath);
        }

        return overrideProblems.Count == 0 ? loaded : throw new GraphException(overrideProblems, fullPath);
    }

    /// <summary>Loads a graph from JSON text; relative paths resolve against <paramref name="virtualPath"/>'s folder.</summary>
    /// <exception cref="GraphException">Every problem found, with JSON paths.</exception>
    public static LoadedGraph LoadFromText(string json, string virtualPath, PluginCatalog catalog, TimeProvider time)
    {
        ArgumentNullException.ThrowIfNull(json);
        ArgumentNullException.ThrowIfNull(catalog);
        ArgumentNullException.ThrowIfNull(time);
        var fullPath = Path.GetFullPath(virtualPath);
        var baseDirectory = Path.GetDirectoryName(fullPath)!;
        JsonDocument document;
        try
        {
            document = JsonDocument.Parse(json, DocumentOptions);
        }
        catch (JsonException ex)
        {
            throw new GraphException([new JsonProblem("$", $"not valid JSON: {ex.Message}")], fullPath);
        }

        using (document)
        {
            var problems = new JsonProblemSink();
            var loaded = Read(document.RootElement, fullPath, baseDirectory, catalog, time, problems);
            if (problems.Problems.Count > 0 || loaded is null)
            {
                throw new GraphException(problems.Problems, fullPath);
            }

            return loaded;
        }
    }

    /// <summary>Writes <paramref name="document"/> as a graph file (the settings the file gave or that differ from their defaults, wires in order).</summary>
    public static void Save(GraphDocument document, string path)
    {
        ArgumentException.ThrowIfNullOrEmpty(path);
        File.WriteAllText(path, ToJson(document), new UTF8Encoding(false));
    }

    /// <summary>The graph file text of <paramref name="document"/>.</summary>
    public static string ToJson(GraphDocument document)
    {
        ArgumentNullException.ThrowIfNull(document);
        using var stream = new MemoryStream();
        using (var writer = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            writer.WriteStartObject();
            writer.WriteString("schema", GraphDocument.Schema);
            if (document.Robot is not null)
            {
                writer.WriteString("robot", document.Robot);
            }

            writer.WriteString("transport", document.Transport);
            writer.WriteNumber("loop_rate_hz", document.LoopRateHz);
            writer.WriteStartArray("instances");
            foreach (var instance in document.Instances)
            {
                writer.WriteStartObject();
                writer.WriteString("name", instance.Name);
                writer.WriteString("type", instance.Type);
                if (instance.Settings is not null && (instance.Written is not null || SettingsSchema.For(instance.Settings.GetType()).Given(instance.Settings).Count > 0))
                {
                    writer.WritePropertyName("settings");
                    SettingsSchema.For(instance.Settings.GetType()).Write(writer, instance.Settings, instance.Written);
                }

                writer.WriteEndObject();
            }

            writer.WriteEndArray();
            writer.WriteStartArray("wires");
            foreach (var wire in document.Wires)
            {
                writer.WriteStartObject();
                writer.WriteString("from", wire.From);
                writer.WriteString("to", wire.To);
                if (wire.Delayed)
                {
                    writer.WriteBoolean("delayed", true);
                }

                writer.WriteEndObject();
            }

            writer.WriteEndArray();
            if (document.Layout is { Count: > 0 } layout)
            {
                GraphLayout.Write(writer, layout);
            }

            writer.WriteEndObject();
        }

        return Encoding.UTF8.GetString(stream.ToArray()) + Environment.NewLine;
    }

    private static LoadedGraph? Read(JsonElement root, string fullPath, string baseDirectory, PluginCatalog catalog, TimeProvider time, JsonProblemSink problems)
    {
        if (root.ValueKind != JsonValueKind.Object)
        {
            problems.Add("$", "expected a JSON object");
            return null;
        }

        var r = new JsonFieldReader(problems, root, "$", JsonWording.Brief);
        r.RejectFieldsOtherThan(TopLevel);
        var schema = r.StringOrNull("schema");
        if (schema != GraphDocument.Schema)
        {
            problems.Add("$.schema", $"expected \"{GraphDocument.Schema}\"");
        }

        var robotPath = r.StringOrNull("robot");
        RobotDefinition? robot = null;
        if (robotPath is not null)
        {
            try
            {
                robot = RobotLoader.Load(Path.Combine(baseDirectory, robotPath));
            }
            catch (RobotDataException ex)
            {
                problems.Add("$.robot", $"robot file '{robotPath}' is invalid: {ex.Message}");
            }
        }

        var transport = r.StringOrNull("transport") ?? "virtual";
        var rate = GraphDocument.DefaultLoopRateHz;
        if (r.Raw("loop_rate_hz", required: false) is { } rateJson)
        {
            if (rateJson.ValueKind != JsonValueKind.Number || !LoopRate.IsValid(rate = rateJson.GetDouble()))
            {
                problems.Add("$.loop_rate_hz", $"expected a number within {LoopRate.RangeText} (Hz)");
                rate = GraphDocument.DefaultLoopRateHz;
            }
        }

        var graph = new PluginGraph();
        RobotNode? robotNode = null;
        if (robot is not null)
        {
            robotNode = new RobotNode(robot, time, baseDirectory);
            graph.Add(robotNode);
        }

        var instances = ReadInstances(root, baseDirectory, robot, catalog, time, graph, problems);

        // Instances named in the file that could not be created: their problems are reported already, and their wires
        // cannot be checked without them.
        var failed = new HashSet<string>(StringComparer.Ordinal);
        if (root.TryGetProperty("instances", out var declared) && declared.ValueKind == JsonValueKind.Array)
        {
            foreach (var item in declared.EnumerateArray())
            {
                if (item.ValueKind == JsonValueKind.Object && item.TryGetProperty("name", out var n) && n.ValueKind == JsonValueKind.String && graph.Find(n.GetString()!) is null)
                {
                    failed.Add(n.GetString()!);
                }
            }
        }

        var wires = ReadWires(root, graph, problems, failed);
        var declaredNames = new HashSet<string>(instances.Select(i => i.Name).Concat(failed), StringComparer.Ordinal);
        var layout = GraphLayout.Read(root, declaredNames, robot is not null || robotPath is not null, problems);

        // A cycle (or an observer feeding others) is listed with the problems above, among the instances and wires
        // that could be created, rather than only once those are fixed.
        foreach (var p in graph.Check())
        {
            problems.Add(p.Path, p.Message);
        }

        if (problems.Problems.Count > 0)
        {
            return null;
        }

        var program = graph.Compile();

        var document = new GraphDocument(robotPath, transport, rate, instances, wires) { Layout = layout };
        return new LoadedGraph(fullPath, document, robot, robotNode, graph, program);
    }

    private static List<InstanceSpec> ReadInstances(JsonElement root, string baseDirectory, RobotDefinition? robot, PluginCatalog catalog, TimeProvider time, PluginGraph graph, JsonProblemSink problems)
    {
        var specs = new List<InstanceSpec>();
        if (!root.TryGetProperty("instances", out var array) || array.ValueKind != JsonValueKind.Array)
        {
            problems.Add("$.instances", "expected an array of instances");
            return specs;
        }

        var i = -1;
        foreach (var item in array.EnumerateArray())
        {
            i++;
            var at = string.Create(CultureInfo.InvariantCulture, $"$.instances[{i}]");
            if (item.ValueKind != JsonValueKind.Object)
            {
                problems.Add(at, "expected an object with name, type and settings");
                continue;
            }

            var fields = new JsonFieldReader(problems, item, at, JsonWording.Brief);
            fields.RejectFieldsOtherThan("name", "type", "settings");
            var name = NullIfEmpty(fields.String("name"));
            var typeName = NullIfEmpty(fields.String("type"));
            if (name is not null)
            {
                var nameProblem = name == RobotNode.InstanceName && robot is not null
                    ? $"'{RobotNode.InstanceName}' is the robot's instance name"
                    : graph.CheckName(name);
                if (nameProblem is not null)
                {
                    problems.Add($"{at}.name", nameProblem);
                    name = null;
                }
            }

            if (typeName is null)
            {
                continue;
            }

            var type = catalog.Find(typeName);
            if (type is null)
            {
                problems.Add($"{at}.type", $"unknown plug-in type '{typeName}' (known: {string.Join(", ", catalog.Types.Select(t => t.Name).Order(StringComparer.Ordinal))})");
                continue;
            }

            PluginSettings? settings = null;
            var settingsJson = item.TryGetProperty("settings", out var s) ? s : default;
            if (type.Settings is not null)
            {
                var errors = new List<JsonProblem>();
                settings = type.Settings.Read(settingsJson, errors);
                AddUnder(problems, errors, $"{at}.settings");
                if (settings is null)
                {
                    continue;
                }
            }
            else if (settingsJson.ValueKind == JsonValueKind.Object && settingsJson.EnumerateObject().Any())
            {
                problems.Add($"{at}.settings", $"plug-in type '{typeName}' has no settings");
                continue;
            }

            if (name is null)
            {
                continue;
            }

            try
            {
                var plugin = type.Create(settings, new PluginContext(name, robot, time, baseDirectory) { DeviceOpener = catalog.DeviceOpener });
                graph.Add(plugin);
                specs.Add(new InstanceSpec(name, typeName, settings)
                {
                    Written = settingsJson.ValueKind == JsonValueKind.Object ? [.. settingsJson.EnumerateObject().Select(p => p.Name)] : null,
                });
            }
            catch (SettingsException ex)
            {
                AddUnder(problems, ex.Errors, $"{at}.settings");
            }
#pragma warning disable CA1031 // a plug-in constructor may fail in any way (missing file, bad robot); report it at the instance
            catch (Exception ex)
#pragma warning restore CA1031
            {
                problems.Add(at, $"'{name}' ({typeName}) could not be created: {ex.Message}");
            }
        }

        return specs;
    }

    private static List<Wire> ReadWires(JsonElement root, PluginGraph graph, JsonProblemSink problems, HashSet<string> failed)
    {
        var wires = new List<Wire>();
        if (!root.TryGetProperty("wires", out var array))
        {
            return wires;
        }

        if (array.ValueKind != JsonValueKind.Array)
        {
            problems.Add("$.wires", "expected an array of wires");
            return wires;
        }

        var i = -1;
        foreach (var item in array.EnumerateArray())
        {
            i++;
            var at = string.Create(CultureInfo.InvariantCulture, $"$.wires[{i}]");
            if (item.ValueKind != JsonValueKind.Object)
            {
                problems.Add(at, "expected an object with from, to and optionally delayed");
                continue;
            }

            var fields = new JsonFieldReader(problems, item, at, JsonWording.Brief);
            fields.RejectFieldsOtherThan("from", "to", "delayed");
            var from = NullIfEmpty(fields.String("from"));
            var to = NullIfEmpty(fields.String("to"));
            var delayed = fields.Raw("delayed", required: false) is { } d && (fields.ReadBoolean(d, $"{at}.delayed") ?? false);

            if (from is null || to is null)
            {
                continue;
            }

            if ((SignalName.TrySplit(from, out var fromInstance, out _) && failed.Contains(fromInstance))
                || (SignalName.TrySplit(to, out var toInstance, out _) && failed.Contains(toInstance)))
            {
                continue; // the instance's own problems are reported; its wires cannot be checked without it
            }

            var wire = new Wire(from, to, delayed, at);
            var problem = graph.TryConnect(wire);
            if (problem is null)
            {
                wires.Add(wire);
                continue;
            }

            // Point at the end that is wrong when we can tell.
            var field = problem.Contains($"'{to}'", StringComparison.Ordinal) && !problem.Contains($"'{from}'", StringComparison.Ordinal) ? "to" : "from";
            if (problem.StartsWith("input ", StringComparison.Ordinal))
            {
                field = "to";
            }

            problems.Add($"{at}.{field}", problem);
        }

        return wires;
    }

    private static string? NullIfEmpty(string value) => value.Length == 0 ? null : value;

    private static void AddUnder(JsonProblemSink problems, IEnumerable<JsonProblem> settingProblems, string settingsPath)
    {
        foreach (var p in settingProblems.Select(e => e.Under(settingsPath)))
        {
            problems.Add(p.Path, p.Message);
        }
    }
}
