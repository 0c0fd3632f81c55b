using System.Diagnostics;
using System.Net;
using System.Net.Http.Json;
using System.Text.Json;
using System.Text.Json.Nodes;

namespace RobotControl.WebConsole.Tests.Editor;

/// <summary>
/// The editor's API is read-only for watchers, and reads files only inside the graphs and robot folders: a symbolic
/// link or an absolute path out of them, or a FIFO, is refused at once with one line that quotes nothing of the file.
/// </summary>
[Collection(EditorCollection.Name)]
[System.Runtime.Versioning.SupportedOSPlatform("linux")]
public sealed class EditorSecurityTests(EditorFixture console)
{
    private const string Secret = "SECRET-CONTENT-29";

    [Fact]
    public async Task A_watcher_cannot_save_a_graph_not_even_the_running_one()
    {
        using var holder = await console.Operator("editor-operator");
        using var watcher = console.Client("editor-watcher");
        var running = Path.Combine(console.Graphs, "teleop-lb.json");
        var before = File.ReadAllText(running);
        var graph = JsonNode.Parse(File.ReadAllText(Path.Combine(console.Graphs, EditorFixture.HandWritten)));

        var reply = await watcher.PutAsJsonAsync("api/editor/graphs/teleop-lb.json", new { graph });

        Assert.Equal(HttpStatusCode.Forbidden, reply.StatusCode);
        Assert.Equal(before, File.ReadAllText(running));
        Assert.Equal(HttpStatusCode.Forbidden, (await watcher.PutAsJsonAsync("api/editor/graphs/new-by-watcher.json", new { graph })).StatusCode);
        Assert.False(File.Exists(Path.Combine(console.Graphs, "new-by-watcher.json")));
        await holder.DeleteAsync("api/operator");
    }

    [Fact]
    public async Task Files_outside_the_folders_are_refused_and_never_quoted()
    {
        var outside = Directory.CreateTempSubdirectory("rc-outside").FullName;
        try
        {
            var secret = Path.Combine(outside, "secret.json");
            File.WriteAllText(secret, $"{{\"{Secret}\": 1}}");
            File.SetUnixFileMode(secret, UnixFileMode.UserRead | UnixFileMode.UserWrite);
            File.CreateSymbolicLink(Path.Combine(console.Graphs, "leak.json"), secret);
            File.CreateSymbolicLink(Path.Combine(console.Graphs, "leak.csv"), secret);
            using var http = console.Client("file-prober");

            var read = await http.GetAsync("api/editor/graphs/leak.json");
            await AssertRefused(read, HttpStatusCode.BadRequest, "graph: 'leak.json' is outside the graphs folder and the robot folder");

            var robot = await Check(http, g => g["robot"] = secret);
            Assert.Equal($"robot: '{secret}' is outside the graphs folder and the robot folder (links that leave them are not followed)", Problem(robot, "$.robot"));

            var playback = await Check(http, g => g["instances"]!.AsArray().Add(Playback("leak.csv")));
            Assert.StartsWith("path: 'leak.csv' is outside the graphs folder", Problem(playback, "$.instances[7].settings.path"), StringComparison.Ordinal);

            var catalog = await http.GetAsync($"api/editor/catalog?robot={Uri.EscapeDataString(secret)}");
            await AssertRefused(catalog, HttpStatusCode.BadRequest, $"robot: '{secret}' is outside");
        }
        finally
        {
            File.Delete(Path.Combine(console.Graphs, "leak.json"));
            File.Delete(Path.Combine(console.Graphs, "leak.csv"));
            Directory.Delete(outside, recursive: true);
        }
    }

    [Fact]
    public async Task A_fifo_named_as_a_recording_is_answered_at_once_with_a_clear_problem()
    {
        var fifo = Path.Combine(console.Graphs, "stuck.csv");
        using (var mkfifo = Process.Start("mkfifo", fifo))
        {
            mkfifo.WaitForExit();
        }

        try
        {
            using var http = console.Client("fifo-prober");
            http.Timeout = TimeSpan.FromSeconds(20); // a hang (the FIFO opened) fails here instead of never
            var check = await Check(http, g => g["instances"]!.AsArray().Add(Playback("stuck.csv")));
            Assert.Equal("path: 'stuck.csv' is not a regular file (a FIFO, socket or device is never opened)", Problem(check, "$.instances[7].settings.path"));
            var read = await http.GetAsync("api/editor/graphs/stuck.csv");
            Assert.Equal(HttpStatusCode.BadRequest, read.StatusCode); // not a .json name: refused before any file is looked at
        }
        finally
        {
            File.Delete(fifo);
        }
    }

    [Fact]
    public async Task An_over_long_graph_name_is_a_json_400_naming_the_field_and_the_limit()
    {
        using var http = await console.Operator("long-graph-name");
        var name = new string('g', 300) + ".json";
        var graph = JsonNode.Parse(File.ReadAllText(Path.Combine(console.Graphs, EditorFixture.HandWritten)));

        await AssertRefused(await http.PutAsJsonAsync($"api/editor/graphs/{name}", new { graph }), HttpStatusCode.BadRequest, "name: a graph file name has at most 100 characters (this one has 305)");
        await AssertRefused(await http.GetAsync($"api/editor/graphs/{name}"), HttpStatusCode.BadRequest, "name: a graph file name has at most 100 characters");
        await AssertRefused(await http.PostAsJsonAsync("api/editor/check", new { name, graph }), HttpStatusCode.BadRequest, "name: a graph file name has at most 100 characters");
        await http.DeleteAsync("api/operator");
    }

    private static JsonObject Playback(string file) => new() { ["name"] = "player", ["type"] = "playback", ["settings"] = new JsonObject { ["path"] = file } };

    private async Task<JsonElement> Check(HttpClient http, Action<JsonObject> change)
    {
        var graph = JsonNode.Parse(File.ReadAllText(Path.Combine(console.Graphs, EditorFixture.HandWritten)))!.AsObject();
        change(graph);
        var reply = await http.PostAsJsonAsync("api/editor/check", new { name = "probe.json", graph });
        var text = await reply.Content.ReadAsStringAsync();
        Assert.True(reply.StatusCode == HttpStatusCode.OK, text);
        Assert.DoesNotContain(Secret, text, StringComparison.Ordinal);
        return JsonDocument.Parse(text).RootElement.Clone();
    }

    private static string Problem(JsonElement check, string path) =>
        check.GetProperty("problems").EnumerateArray().Single(p => p.GetProperty("path").GetString() == path).GetProperty("message").GetString()!;

    private static async Task AssertRefused(HttpResponseMessage reply, HttpStatusCode status, string start)
    {
        var text = await reply.Content.ReadAsStringAsync();
        Assert.Equal(status, reply.StatusCode);
        Assert.DoesNotContain(Secret, text, StringComparison.Ordinal);
        var error = JsonDocument.Parse(text).RootElement.GetProperty("error").GetString()!;
        Assert.StartsWith(start, error, StringComparison.Ordinal);
        Assert.DoesNotContain('\n', error);
    }
}
