using System.Text.Json.Nodes;
using System.Text.RegularExpressions;
using Microsoft.Playwright;
using RobotControl.WebConsole.Adapter;
using RobotControl.WebConsole.Editor;
using RobotControl.WebConsole.Server;

namespace RobotControl.WebConsole.Tests.Editor;

/// <summary>
/// A console with the graph editor on the virtual robot, over a scratch graphs folder (a copy of
/// graphs/teleop-lb.json and the hand-written one-arm graph; <c>hardware/</c> and the trajectories linked from the
/// repository, so the graphs' relative paths resolve as in <c>graphs/</c>). Its collection runs alone: a second
/// virtual robot in real time beside the other console would measure the shared machine.
/// </summary>
public sealed class EditorFixture : IAsyncLifetime
{
    public const string HandWritten = "teleop-lb-right.json";

    private HeadlessChromium? _chromium;

    public string Root { get; } = Path.Combine(Path.GetTempPath(), $"rc-editor-{Guid.NewGuid():N}");

    public string Graphs => Path.Combine(Root, "graphs");

    public SwitchableSession Session { get; private set; } = null!;

    public GraphRunner Runner { get; private set; } = null!;

    public ConsoleServer Server { get; private set; } = null!;

    public IBrowser Browser => _chromium?.Browser ?? throw new InvalidOperationException("no browser");

    public async Task InitializeAsync()
    {
        var repo = ConsoleFixture.RepoRoot;
        Directory.CreateDirectory(Graphs);
        Directory.CreateSymbolicLink(Path.Combine(Root, "hardware"), Path.Combine(repo, "hardware"));
        Directory.CreateDirectory(Path.Combine(Graphs, "trajectories")); // a copy: a link leaving the graphs folder is refused (ConfinedFiles)
        foreach (var file in Directory.EnumerateFiles(Path.Combine(repo, "graphs", "trajectories")))
        {
            File.Copy(file, Path.Combine(Graphs, "trajectories", Path.GetFileName(file)));
        }
        File.Copy(Path.Combine(repo, "graphs", "teleop-lb.json"), Path.Combine(Graphs, "teleop-lb.json"));
        File.Copy(Path.Combine(repo, "tests", "RobotControl.Console.Tests", "Editor", HandWritten), Path.Combine(Graphs, HandWritten));

        var options = new LiveSessionOptions { GraphPath = Path.Combine(Graphs, "teleop-lb.json"), Catalog = ConsoleFixture.Catalog(), Virtual = true };
        var first = new LiveSession(options);
        Session = new SwitchableSession(first);
        Runner = new GraphRunner(Session, options.GraphPath, first.Transport, path => new LiveSession(options with { GraphPath = path }));
        var editor = new GraphEditor(new GraphFolder(Graphs), options.Catalog, Runner);
        Server = await ConsoleServer.StartAsync(Session, BindAddress.Parse("127.0.0.1:0"), null, editor: editor);
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
        Runner.Dispose();
        Directory.Delete(Root, recursive: true);
    }

    /// <summary>An HTTP client holding the operator role (taken from whoever held it): saving and starting are the operator's.</summary>
    public async Task<HttpClient> Operator(string client)
    {
        if (Server.Operator.Holder is { } holder)
        {
            Server.Operator.Release(holder);
        }

        var http = Client(client);
        (await http.PostAsync("api/operator", null)).EnsureSuccessStatusCode();
        return http;
    }

    /// <summary>A new browser context on the editor page, once its palette and first check are in.</summary>
    public async Task<IPage> OpenEditor(int width = 2560, int height = 1440)
    {
        var page = await Browser.NewPageAsync(new() { ViewportSize = new() { Width = width, Height = height } });
        await page.GotoAsync(ConsoleFixture.PageUrl(Server, "editor"));
        await page.Locator(".ged-type[data-type=clutch]").WaitForAsync();
        await page.Locator("[data-testid=problems][data-count]").WaitForAsync();
        return page;
    }

    /// <summary>Loads graph file <paramref name="graph"/> of the folder in the editor, and waits until it is checked without problems.</summary>
    public static async Task LoadWithoutProblems(IPage page, string graph)
    {
        await page.GetByTestId("graph-list").SelectOptionAsync(graph);
        await page.GetByTestId("load").ClickAsync();
        await page.Locator("#message").Filter(new() { HasTextString = $"loaded {graph}" }).WaitForAsync();
        await page.Locator("[data-testid=problems][data-count='0']").WaitForAsync();
    }

    /// <summary>Zooms the editor's canvas in by one step of the wheel (with Ctrl, as drawflow zooms), over its middle.</summary>
    public static async Task ZoomInOneStep(IPage page)
    {
        var box = (await page.GetByTestId("graph-canvas").BoundingBoxAsync())!;
        await page.Mouse.MoveAsync(box.X + box.Width / 2, box.Y + box.Height / 2);
        await page.Keyboard.DownAsync("Control");
        await page.Mouse.WheelAsync(0, -100);
        await page.Keyboard.UpAsync("Control");
    }

    /// <summary>
    /// Once a graph is loaded (and fitted: its check's problem count can come first), zooms the editor's canvas in
    /// until its nodes show their labels (zoomed out, a node shows only its name).
    /// </summary>
    public static async Task ZoomInUntilLabelsShow(IPage page)
    {
        await page.Locator("#message").Filter(new() { HasTextString = "loaded " }).WaitForAsync();
        for (var step = 0; step < 12 && await page.Locator("[data-testid=graph-canvas].compact").CountAsync() > 0; step++)
        {
            await ZoomInOneStep(page);
        }
    }

    /// <summary>Gives up the page's operator role (if it took it) and closes it.</summary>
    public static async Task CloseEditor(IPage page)
    {
        await page.EvaluateAsync("() => fetch('/api/operator', { method: 'DELETE', headers: { 'X-Console-Client': sessionStorage.getItem('rc-console-client'), Authorization: 'Bearer ' + sessionStorage.getItem('rc-console-token') } })");
        await page.CloseAsync();
    }

    /// <summary>
    /// The one-arm graph with three problems at once: an out-of-range ratio (scaling_right), an instance of a type
    /// nobody knows (mystery) and the feedback wire damping_right.fx -> touch_right.force_x no longer delayed (a cycle
    /// through the arm: touch_right -> homing_right -> clutch_right -> ik_right -> walls_right -> damping_right).
    /// </summary>
    public string GraphWithThreeProblems()
    {
        var graph = JsonNode.Parse(File.ReadAllText(Path.Combine(Graphs, HandWritten)))!.AsObject();
        graph["instances"]![2]!["settings"]!["ratio"] = 500;
        graph["instances"]!.AsArray().Add(new JsonObject { ["name"] = "mystery", ["type"] = "no_such_type" });
        foreach (var wire in graph["wires"]!.AsArray())
        {
            if ((string?)wire!["from"] == "damping_right.fx")
            {
                wire.AsObject().Remove("delayed");
            }
        }

        return graph.ToJsonString();
    }

    /// <summary>The instances of <see cref="GraphWithThreeProblems"/>'s cycle.</summary>
    public static readonly string[] CycleOfThree = ["clutch_right", "damping_right", "homing_right", "ik_right", "touch_right", "walls_right"];

    /// <summary>The instances a cycle problem names (<c>cycle without a delayed wire: a -> b -> a (wires: ...</c>), in order, or none.</summary>
    public static string[] CycleIn(string problem)
    {
        var chain = Regex.Match(problem, @"cycle without a delayed wire: (\S+(?: -> \S+)+) \(wires: ");
        var names = chain.Success ? chain.Groups[1].Value.Split(" -> ") : [];
        return names.Length > 2 && names[0] == names[^1] ? names[..^1] : [];
    }

    /// <summary>An HTTP client that names itself <paramref name="client"/>.</summary>
    public HttpClient Client(string client)
    {
        return ConsoleFixture.Client(Server, client);
    }
}

[CollectionDefinition(Name, DisableParallelization = true)]
public sealed class EditorCollection : ICollectionFixture<EditorFixture>
{
    public const string Name = "graph editor on the virtual robot";
}
