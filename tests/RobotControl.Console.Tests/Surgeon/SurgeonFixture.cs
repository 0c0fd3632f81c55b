using System.Globalization;
using System.Text;
using System.Text.Json.Nodes;
using Microsoft.Playwright;
using RobotControl.WebConsole.Adapter;
using RobotControl.WebConsole.Server;

namespace RobotControl.WebConsole.Tests.Surgeon;

/// <summary>
/// A console for the surgeon's view on the virtual robot: the shipped teleop graph with a scripted pedal box added
/// (pedal 1 drives the robot node's <c>pedal</c>: PEDAL_UP/PEDAL_DOWN; pedal 2 the right clutch, in place of the
/// Touch's button), on the shipped robot file with the operator's E-STOP configured to switch the motors off. Built
/// in a temporary folder; the pedal script repeats every <see cref="Period"/> seconds of loop time.
/// </summary>
public sealed class SurgeonFixture : IAsyncLifetime
{
    /// <summary>Pedal script period, s: pedal 1 down in [1, 3), pedal 2 (right clutch) down in [4, 7).</summary>
    public const double Period = 8;

    private readonly string _folder = Path.Combine(Path.GetTempPath(), $"rc-surgeon-{Guid.NewGuid():N}");
    private HeadlessChromium? _chromium;

    public LiveSession Session { get; private set; } = null!;

    public ConsoleServer Server { get; private set; } = null!;

    public IBrowser Browser => _chromium?.Browser ?? throw new InvalidOperationException("no browser");

    public string GraphPath => Path.Combine(_folder, "surgeon.json");

    public async Task InitializeAsync()
    {
        Directory.CreateDirectory(_folder);
        WriteRobotAndGraph(_folder);
        Session = new LiveSession(new LiveSessionOptions { GraphPath = GraphPath, Catalog = ConsoleFixture.Catalog(), Virtual = true });
        Server = await ConsoleServer.StartAsync(Session, BindAddress.Parse("127.0.0.1:0"), null);
        _chromium = await HeadlessChromium.LaunchAsync();
    }

    public async Task DisposeAsync()
    {
        if (_chromium is not null)
        {
            await _chromium.DisposeAsync();
        }

        await Server.DisposeAsync();
        Session.Dispose();
        Directory.Delete(_folder, recursive: true);
    }

    /// <summary>Writes the robot file (operator E-STOP: torque off) and the graph with the scripted pedals into <paramref name="folder"/>.</summary>
    public static void WriteRobotAndGraph(string folder)
    {
        var root = ConsoleFixture.RepoRoot;
        var robotFile = Path.Combine(root, "hardware", "robots", "lb-1.0.json");
        var robot = JsonNode.Parse(File.ReadAllText(robotFile))!.AsObject();
        robot["component_catalogs"] = new JsonArray([.. robot["component_catalogs"]!.AsArray().Select(c => (JsonNode)Path.GetFullPath(Path.Combine(Path.GetDirectoryName(robotFile)!, c!.GetValue<string>())))]);
        robot["safety"] = new JsonObject { ["safe_state"] = new JsonObject { ["operator"] = "torque_off" } };
        File.WriteAllText(Path.Combine(folder, "lb-estop-off.json"), robot.ToJsonString());

        var graphs = Path.Combine(root, "graphs");
        var graph = JsonNode.Parse(File.ReadAllText(Path.Combine(graphs, "teleop-lb.json")))!.AsObject();
        graph["robot"] = "lb-estop-off.json";
        foreach (var instance in graph["instances"]!.AsArray())
        {
            if (instance!["settings"]?["script"] is { } script)
            {
                instance["settings"]!["script"] = Path.Combine(graphs, script.GetValue<string>());
            }
        }

        graph["instances"]!.AsArray().Add(new JsonObject
        {
            ["name"] = "pedals",
            ["type"] = "foot_pedals",
            ["settings"] = new JsonObject { ["script"] = PeriodicScript(), ["pedals"] = 2 },
        });
        var wires = graph["wires"]!.AsArray();
        var button = wires.Single(w => w!["to"]!.GetValue<string>() == "clutch_right.clutch");
        button!["from"] = "pedals.pedal2";
        wires.Add(new JsonObject { ["from"] = "pedals.pedal1", ["to"] = "robot.pedal" });
        File.WriteAllText(Path.Combine(folder, "surgeon.json"), graph.ToJsonString());
    }

    /// <summary>An HTTP client that names itself <paramref name="client"/>, holding the operator role (taken from whoever held it) when <paramref name="operate"/>.</summary>
    public async Task<HttpClient> Client(string client, bool operate)
    {
        if (operate && Server.Operator.Holder is { } holder)
        {
            Server.Operator.Release(holder);
        }

        var http = ConsoleFixture.Client(Server, client);
        if (operate)
        {
            (await http.PostAsync("api/operator", null)).EnsureSuccessStatusCode();
        }

        return http;
    }

    /// <summary>The latest value of a ring signal.</summary>
    public double Latest(string signal)
    {
        var ring = Session.Signals;
        var column = ring.IndexOf(signal);
        Assert.True(column >= 0, $"no signal {signal}");
        return ring.Read(ring.Written - 1, [column], 1).Values[0][0];
    }

    /// <summary>Waits (up to <paramref name="seconds"/>) until <paramref name="condition"/> holds.</summary>
    public static async Task Until(Func<bool> condition, string what, double seconds = 20)
    {
        var end = DateTime.UtcNow.AddSeconds(seconds);
        while (!condition())
        {
            Assert.True(DateTime.UtcNow < end, $"timed out waiting for {what}");
            await Task.Delay(20);
        }
    }

    private static string PeriodicScript()
    {
        var steps = new StringBuilder();
        for (var k = 0; k < 100; k++)
        {
            var t = k * Period;
            steps.Append(CultureInfo.InvariantCulture, $"{t + 1}:1,{t + 3}:0,{t + 4}:2,{t + 7}:0,");
        }

        return steps.ToString().TrimEnd(',');
    }
}

[CollectionDefinition(Name)]
public sealed class SurgeonCollection : ICollectionFixture<SurgeonFixture>
{
    public const string Name = "surgeon's view on the virtual robot";
}
