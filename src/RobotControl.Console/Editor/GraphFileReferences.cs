using System.Text.Json;
using RobotControl.Runtime.Discovery;

namespace RobotControl.WebConsole.Editor;

/// <summary>
/// The files a graph's text names (its <c>robot</c> and every setting its type marks as a file path), checked against
/// the editor's <see cref="ConfinedFiles"/> before the graph-file loader opens any of them.
/// </summary>
internal static class GraphFileReferences
{
    /// <summary>One problem per file <paramref name="json"/> names that <paramref name="files"/> refuses (none for text that is not JSON: the loader says so).</summary>
    public static IReadOnlyList<ProblemView> Problems(string json, PluginCatalog catalog, string folder, ConfinedFiles files)
    {
        var problems = new List<ProblemView>();
        try
        {
            using var document = JsonDocument.Parse(json, new JsonDocumentOptions { CommentHandling = JsonCommentHandling.Skip });
            var root = document.RootElement;
            if (root.ValueKind != JsonValueKind.Object)
            {
                return problems;
            }

            if (root.TryGetProperty("robot", out var robot) && robot.ValueKind == JsonValueKind.String && robot.GetString() is { Length: > 0 } robotFile)
            {
                Add(problems, "$.robot", files.Problem("robot", robotFile, Path.Combine(folder, robotFile)));
            }

            if (!root.TryGetProperty("instances", out var instances) || instances.ValueKind != JsonValueKind.Array)
            {
                return problems;
            }

            var index = 0;
            foreach (var instance in instances.EnumerateArray())
            {
                Instance(problems, instance, $"$.instances[{index++}]", catalog, folder, files);
            }
        }
        catch (JsonException)
        {
            // Not JSON: the loader reports it.
        }

        return problems;
    }

    private static void Instance(List<ProblemView> problems, JsonElement instance, string path, PluginCatalog catalog, string folder, ConfinedFiles files)
    {
        if (instance.ValueKind != JsonValueKind.Object
            || !instance.TryGetProperty("type", out var type) || type.ValueKind != JsonValueKind.String
            || catalog.Find(type.GetString()!)?.Settings is not { } schema
            || !instance.TryGetProperty("settings", out var settings) || settings.ValueKind != JsonValueKind.Object)
        {
            return;
        }

        foreach (var setting in settings.EnumerateObject())
        {
            if (schema.Find(setting.Name) is { IsFilePath: true } && setting.Value.ValueKind == JsonValueKind.String && setting.Value.GetString() is { Length: > 0 } file)
            {
                Add(problems, $"{path}.settings.{setting.Name}", files.Problem(setting.Name, file, Path.Combine(folder, file), folderToo: true));
            }
        }
    }

    private static void Add(List<ProblemView> problems, string path, string? problem)
    {
        if (problem is not null)
        {
            problems.Add(new ProblemView(path, problem));
        }
    }
}
