using System.Net.Http.Json;
using Microsoft.Playwright;
using RobotControl.Host.Harness;
using RobotControl.Plugins.Standard.Conditioning;
using RobotControl.Plugins.Touch;
using RobotControl.Runtime.Discovery;
using RobotControl.WebConsole.Adapter;
using RobotControl.TestSupport;
using RobotControl.WebConsole.Server;

namespace RobotControl.WebConsole.Tests;

/// <summary>
/// One console on the virtual robot (graphs/teleop-lb.json, real firmware, real time) shared by the tests of the
/// collection, plus headless Chromium (Debian's, at /usr/bin/chromium; SwiftShader for WebGL).
/// </summary>
public sealed class ConsoleFixture : IAsyncLifetime
{
    public const string ChromiumPath = DebianChromium.Path;

    /// <summary>Chromium's switches (<see cref="DebianChromium.Args"/>).</summary>
    public static readonly string[] ChromiumArgs = [.. DebianChromium.Args];

    private HeadlessChromium? _chromium;

    public LiveSession Session { get; private set; } = null!;

    public ConsoleServer Server { get; private set; } = null!;

    public IBrowser Browser => _chromium?.Browser ?? throw new InvalidOperationException("no browser");

    public static string RepoRoot
    {
        get
        {
            var dir = new DirectoryInfo(AppContext.BaseDirectory);
            while (dir is not null && !File.Exists(Path.Combine(dir.FullName, "RobotControl.sln")))
            {
                dir = dir.Parent;
            }

            return dir?.FullName ?? throw new InvalidOperationException("repository root not found");
        }
    }

    public static PluginCatalog Catalog() => PluginCatalog.FromAssemblies(typeof(ClutchPlugin).Assembly, typeof(TouchPlugin).Assembly);

    /// <summary>A console session on the virtual LB-1.0 running <c>graphs/teleop-lb.json</c>, with <paramref name="inject"/>'s faults.</summary>
    public static LiveSession VirtualSession(FaultInjection? inject = null) => new(new LiveSessionOptions
    {
        GraphPath = Path.Combine(RepoRoot, "graphs", "teleop-lb.json"),
        Catalog = Catalog(),
        Virtual = true,
        Inject = inject ?? FaultInjection.None,
        RecordFolder = RecordFolder,
    });

    /// <summary>Where the record button's files go in the tests (a fresh temporary folder per test run).</summary>
    public static string RecordFolder { get; } = Directory.CreateTempSubdirectory("rc-console-recordings-").FullName;

    public async Task InitializeAsync()
    {
        Session = VirtualSession();
        Server = await ConsoleServer.StartAsync(Session, BindAddress.Parse("127.0.0.1:0"), null);
        _chromium = await HeadlessChromium.LaunchAsync();
    }

    /// <summary>Debian's headless Chromium with <see cref="ChromiumArgs"/>.</summary>
    public static Task<IBrowser> LaunchChromiumAsync(IPlaywright playwright) =>
        playwright.Chromium.LaunchAsync(new BrowserTypeLaunchOptions
        {
            ExecutablePath = ChromiumPath,
            Headless = true,
            Args = ChromiumArgs,
        });

    public async Task DisposeAsync()
    {
        if (_chromium is not null)
        {
            await _chromium.DisposeAsync();
        }

        await Server.DisposeAsync();
        Session.Dispose();
    }

    /// <summary>An HTTP client that names itself <paramref name="client"/>.</summary>
    public HttpClient Client(string client)
    {
        return ConsoleFixture.Client(Server, client);
    }

    /// <summary>An HTTP client of <paramref name="server"/> that names itself <paramref name="client"/> and carries the session's token.</summary>
    public static HttpClient Client(ConsoleServer server, string client)
    {
        var http = new HttpClient { BaseAddress = server.BaseUrl };
        http.DefaultRequestHeaders.Add(OperatorRole.ClientHeader, client);
        http.DefaultRequestHeaders.Authorization = new System.Net.Http.Headers.AuthenticationHeaderValue("Bearer", server.Token);
        return http;
    }

    /// <summary>The page at <paramref name="hash"/> as the printed URL opens it (with the token).</summary>
    public static string PageUrl(ConsoleServer server, string hash) => $"{server.OpenUrl}#{hash}";

    /// <summary>An HTTP client holding the operator role (taken from whoever held it).</summary>
    public async Task<HttpClient> Operator(string client)
    {
        ReleaseOperator();
        var http = Client(client);
        (await http.PostAsync("api/operator", null)).EnsureSuccessStatusCode();
        return http;
    }

    /// <summary>Frees the operator role (between tests).</summary>
    public void ReleaseOperator()
    {
        if (Server.Operator.Holder is { } holder)
        {
            Server.Operator.Release(holder);
        }
    }

    /// <summary>
    /// A fresh browser context (1400x900) on page <paramref name="hash"/>, the role freed first, <paramref name="initScript"/>
    /// run before the page's own; with <paramref name="operate"/> the page takes the operator role.
    /// </summary>
    public async Task<IPage> OpenPage(string hash, bool operate, string? initScript = null)
    {
        ReleaseOperator();
        var context = await Browser.NewContextAsync(new() { ViewportSize = new() { Width = 1400, Height = 900 } });
        if (initScript is not null)
        {
            await context.AddInitScriptAsync(initScript);
        }

        var page = await context.NewPageAsync();
        await page.GotoAsync(PageUrl(Server, hash));
        if (operate)
        {
            await page.Locator("#claim").ClickAsync();
        }

        await Web.PageTests.Expect(page, "#role", operate ? "operator" : "watching");
        await page.WaitForTimeoutAsync(700);
        return page;
    }

    /// <summary>Closes <paramref name="page"/>'s context and frees the role.</summary>
    public async Task ClosePage(IPage page)
    {
        await page.Context.CloseAsync();
        ReleaseOperator();
    }

    /// <summary>A motor's live view from the API.</summary>
    public static async Task<System.Text.Json.JsonElement> Motor(HttpClient http, string name)
    {
        var controllers = await http.GetFromJsonAsync<System.Text.Json.JsonElement>("api/controllers");
        foreach (var c in controllers.EnumerateArray())
        {
            foreach (var m in c.GetProperty("motors").EnumerateArray())
            {
                if (m.GetProperty("name").GetString() == name)
                {
                    return m;
                }
            }
        }

        throw new KeyNotFoundException(name);
    }

    /// <summary>The value of parameter <paramref name="key"/> of a motor as the module holds it.</summary>
    public static double Parameter(System.Text.Json.JsonElement motor, string key) =>
        motor.GetProperty("parameters").EnumerateArray().First(p => p.GetProperty("key").GetString() == key).GetProperty("value").GetDouble();
}

[CollectionDefinition(Name)]
public sealed class ConsoleCollection : ICollectionFixture<ConsoleFixture>
{
    public const string Name = "console on the virtual robot";
}
