using System.Diagnostics;
using System.Text.Json.Nodes;

namespace RobotControl.TestSupport.Mcap;

/// <summary>
/// Reads MCAP files with the official TypeScript reader, <c>@mcap/core</c> (installed by the console's front-end
/// <c>npm ci</c>, as its other packages), through <c>mcap-check.cjs</c>: what it counts per topic with its streaming
/// reader (chunk CRCs checked, the data section CRC checked) and, for a finished file, with its indexed reader (the
/// summary CRC checked), and the first error it raised.
/// </summary>
public static class McapCheck
{
    /// <summary>The console's front-end folder, whose <c>node_modules</c> holds <c>@mcap/core</c>.</summary>
    public static string WebFolder => RepositoryPaths.Of("src/RobotControl.Console/web");

    /// <summary>Reads <paramref name="file"/> with <c>@mcap/core</c>.</summary>
    public static McapCheckResult Read(string file)
    {
        var core = Path.Combine(WebFolder, "node_modules", "@mcap", "core", "package.json");
        if (!File.Exists(core))
        {
            throw new InvalidOperationException($"@mcap/core is not installed in {WebFolder}: build the Console project without SkipWebBuild (npm ci)");
        }

        var start = new ProcessStartInfo("node") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        start.ArgumentList.Add(RepositoryPaths.Of("tests/RobotControl.TestSupport/Mcap/mcap-check.cjs"));
        start.ArgumentList.Add(WebFolder);
        start.ArgumentList.Add(file);
        using var node = Process.Start(start)!;
        var error = node.StandardError.ReadToEndAsync();
        var output = node.StandardOutput.ReadToEnd();
        node.WaitForExit();
        if (node.ExitCode != 0)
        {
            throw new InvalidOperationException($"node mcap-check.cjs exited {node.ExitCode}: {error.Result}");
        }

        return new McapCheckResult(JsonNode.Parse(output)!.AsObject());
    }
}

/// <summary>What <c>@mcap/core</c> read from one file.</summary>
public sealed record McapCheckResult(JsonObject Raw)
{
    /// <summary>The first error the reader raised (a CRC, a record that does not parse), or null.</summary>
    public string? Error => (string?)Raw["error"];

    /// <summary>True when the streaming reader reached the footer.</summary>
    public bool Complete => (bool?)Raw["stream"]?["complete"] ?? false;

    /// <summary>Messages per topic, streaming reader.</summary>
    public Dictionary<string, long> StreamCounts => Counts(Raw["stream"]?["counts"]);

    /// <summary>Messages per topic, indexed reader (empty for a file cut short).</summary>
    public Dictionary<string, long> IndexedCounts => Counts(Raw["indexed"]?["counts"]);

    /// <summary>Messages per topic in the file's statistics record.</summary>
    public Dictionary<string, long> StatisticsCounts => Counts(Raw["indexed"]?["statistics"]);

    /// <summary>Schemas the streaming reader parsed as JSON.</summary>
    public int Schemas => (int?)Raw["stream"]?["schemas"] ?? 0;

    /// <summary>Messages whose data is not JSON.</summary>
    public int BadJson => (int?)Raw["stream"]?["badJson"] ?? -1;

    /// <summary>Whether the data end's CRC matched the data section (null: no data end read).</summary>
    public bool? DataSectionCrcOk => (bool?)Raw["stream"]?["dataEndCrcOk"];

    /// <summary>Chunk indexes in the summary.</summary>
    public int Chunks => (int?)Raw["indexed"]?["chunks"] ?? 0;

    /// <summary>The compressions the chunk indexes name ("" for uncompressed), each once.</summary>
    public IReadOnlyList<string> Compressions => Raw["indexed"]?["compressions"]?.AsArray().Select(a => (string)a!).ToList() ?? [];

    /// <summary>Attachment names.</summary>
    public IReadOnlyList<string> Attachments => Raw["indexed"]?["attachments"]?.AsArray().Select(a => (string)a!).ToList() ?? [];

    private static Dictionary<string, long> Counts(JsonNode? node) =>
        node?.AsObject().ToDictionary(p => p.Key, p => (long)p.Value!) ?? [];
}
