using System.Globalization;
using System.Text.Json;
using System.Text.Json.Nodes;
using System.Xml.Linq;
using RobotControl.Cli.Commands.Plugins;
using RobotControl.Cli.Commands.Run;
using RobotControl.Plugins.Sdk;

namespace RobotControl.Cli.Tests.Packaging;

/// <summary>
/// The SDK as a lab uses it: pack the SDK, its testing companion and the template into a local feed (from a copy of the
/// sources, in a temporary folder), install the template into a private hive, create a plug-in solution from it,
/// build and test it against the feed, then load the plug-in into a graph with robotctl run --plugins. A second plug-in,
/// built against the same SDK packed as the next major version, must be refused while the first one runs.
/// </summary>
public sealed class SdkPackagingTests : IDisposable
{
    private static readonly string[] PackedSources =
    [
        ".editorconfig", "Directory.Build.props", "Directory.Packages.props", "nuget.config", "global.json",
        "src/RobotControl.Definitions", "src/RobotControl.Plugins.Sdk", "src/RobotControl.Plugins.Sdk.Testing", "templates",
    ];

    private readonly string _dir = Directory.CreateTempSubdirectory("rc-sdkpack-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    [Fact]
    public void A_plugin_from_the_template_builds_tests_loads_and_ticks_and_one_for_another_SDK_major_is_refused()
    {
        var repo = RepoRoot();
        var sources = Path.Combine(_dir, "sources");
        foreach (var path in PackedSources)
        {
            Copy(Path.Combine(repo, path), Path.Combine(sources, path));
        }

        var feed = Path.Combine(_dir, "feed");
        var nextMajorFeed = Path.Combine(_dir, "feed-next-major");
        var host = SdkVersion.Current;
        var nextMajor = $"{host.Major + 1}.0.0";
        var dotnet = new DotnetProcess(Path.Combine(_dir, "packages"));

        // 1. Pack: the SDK (with the robot model it depends on), the testing companion, the template; then the SDK
        //    again as the next major version, the way a future SDK release would be.
        WriteSolution(Path.Combine(sources, "pack.slnx"), "src/RobotControl.Definitions/RobotControl.Definitions.csproj", "src/RobotControl.Plugins.Sdk/RobotControl.Plugins.Sdk.csproj", "src/RobotControl.Plugins.Sdk.Testing/RobotControl.Plugins.Sdk.Testing.csproj", "templates/RobotControl.Templates/RobotControl.Templates.csproj");
        dotnet.Run(sources, "pack", "pack.slnx", "-c", "Release", "-o", feed);
        WriteSolution(Path.Combine(sources, "pack-next-major.slnx"), "src/RobotControl.Definitions/RobotControl.Definitions.csproj", "src/RobotControl.Plugins.Sdk/RobotControl.Plugins.Sdk.csproj");
        dotnet.Run(sources, "pack", "pack-next-major.slnx", "-c", "Release", "-o", nextMajorFeed, $"-p:VersionPrefix={nextMajor}");
        var version = SdkVersion.Format(host);
        foreach (var package in new[] { "RobotControl.Definitions", "RobotControl.Plugins.Sdk", "RobotControl.Plugins.Sdk.Testing", "RobotControl.Templates" })
        {
            Assert.True(File.Exists(Path.Combine(feed, $"{package}.{version}.nupkg")), $"{package}.{version}.nupkg was not packed");
        }

        // 2. Template: install into a private hive (the user's template list is untouched), instantiate twice.
        var work = Path.Combine(_dir, "work");
        Directory.CreateDirectory(work);
        WriteNuGetConfig(Path.Combine(work, "nuget.config"), Path.Combine(repo, "nuget.config"), feed, nextMajorFeed);
        var hive = Path.Combine(_dir, "hive");
        dotnet.Run(work, "new", "install", Path.Combine(feed, $"RobotControl.Templates.{version}.nupkg"), "--debug:custom-hive", hive);
        dotnet.Run(work, "new", "robotcontrol-plugin", "-n", "MyLab.Filters", "-o", "MyLab.Filters", "--debug:custom-hive", hive);
        dotnet.Run(work, "new", "robotcontrol-plugin", "-n", "MyLab.Legacy", "-o", "MyLab.Legacy", "--debug:custom-hive", hive);

        // 3. Build and run the template's own tests against the packed SDK and testing harness.
        var tested = dotnet.Run(Path.Combine(work, "MyLab.Filters"), "test");
        Assert.Matches(@"Passed!\s+- Failed:\s+0, Passed:\s+3", tested);
        dotnet.Run(Path.Combine(work, "MyLab.Legacy"), "build", "src/MyLab.Legacy/MyLab.Legacy.csproj", $"-p:RobotControlSdkVersion={nextMajor}");

        // 4. A plug-ins folder with both, one subfolder each as a lab would deploy them.
        var plugins = Path.Combine(_dir, "plugins");
        Copy(Path.Combine(work, "MyLab.Filters", "src", "MyLab.Filters", "bin", "Debug", "net10.0"), Path.Combine(plugins, "MyLab.Filters"));
        Copy(Path.Combine(work, "MyLab.Legacy", "src", "MyLab.Legacy", "bin", "Debug", "net10.0"), Path.Combine(plugins, "MyLab.Legacy"));
        var legacy = Path.Combine(plugins, "MyLab.Legacy", "MyLab.Legacy.dll");
        var refusal = $"plug-ins: MyLab.Legacy ({legacy}): built against plug-in SDK {nextMajor}, this host has SDK {version} (major versions differ); not loaded, rebuild it against SDK {host.Major}.x";

        // 5. robotctl plugins lists the new type with its assembly, SDK version, ports and settings.
        var listed = new StringWriter();
        var listError = new StringWriter();
        Assert.Equal(0, PluginsCommand.Run(plugins, null, PluginsFormat.Json, listed, listError));
        Assert.Equal(refusal, listError.ToString().TrimEnd());
        using (var listing = JsonDocument.Parse(listed.ToString()))
        {
            var filter = listing.RootElement.GetProperty("plugins").EnumerateArray().Single(p => p.GetProperty("name").GetString() == "mylab_filters_low_pass");
            Assert.Equal(("MyLab.Filters", version), (filter.GetProperty("assembly").GetString(), filter.GetProperty("sdk_version").GetString()));
            Assert.Equal("mm", filter.GetProperty("ports").GetProperty("inputs")[0].GetProperty("units").GetString());
            var cutoff = filter.GetProperty("settings")[0];
            Assert.Equal(("cutoff_hz", 0.1, 200.0), (cutoff.GetProperty("name").GetString(), cutoff.GetProperty("minimum").GetDouble(), cutoff.GetProperty("maximum").GetDouble()));
            Assert.DoesNotContain(listing.RootElement.GetProperty("plugins").EnumerateArray(), p => p.GetProperty("name").GetString() == "mylab_legacy_low_pass");
        }

        // 6. robotctl run --plugins: the filter wired between scaling and clutch of the right arm, every signal recorded.
        var graph = WriteTeleopGraphWithFilter(repo, Path.Combine(_dir, "graph"));
        var (code, output, error) = Cli.Run("run", graph, "--virtual", "--duration", "2s", "--report", Path.Combine(_dir, "graph", "report.json"), "--plugins", plugins);
        Assert.Equal(refusal, error.TrimEnd());
        Assert.True(code == 0, output);
        Assert.Contains("summary: 2000 ticks", output, StringComparison.Ordinal);

        var rows = File.ReadAllLines(Path.Combine(_dir, "graph", "signals.csv"));
        var header = rows[0].Split(',');
        var input = Array.IndexOf(header, "scaling_right.x");
        var filtered = Array.IndexOf(header, "tremor_right.out");
        Assert.True(filtered > 0, "the filter's output was not recorded");
        var values = rows.Skip(1).Select(r => r.Split(',')).Select(c => (In: Parse(c[input]), Out: Parse(c[filtered]))).ToList();
        Assert.Equal(2000, values.Count);
        Assert.Equal(values[0].In, values[0].Out); // the first tick passes the input through

        // Every later tick is the template's first-order filter of what scaling sent (8 Hz cut-off, 1 ms period),
        // and the hand does move (from about 1 s into the demo trajectory).
        var tau = 1 / (2 * Math.PI * 8);
        for (var k = 1; k < values.Count; k++)
        {
            var expected = values[k - 1].Out + ((values[k].In - values[k - 1].Out) * 0.001 / (tau + 0.001));
            Assert.True(Math.Abs(values[k].Out - expected) < 1e-9, $"tick {k}: filter output {values[k].Out}, expected {expected}");
        }

        Assert.True(values.Max(v => Math.Abs(v.Out - v.In)) > 0.01, "the input never moved: nothing was filtered");
    }

    private static double Parse(string text) => double.Parse(text, CultureInfo.InvariantCulture);

    /// <summary>graphs/teleop-lb.json with paths made absolute, the filter inserted on the right arm's x and a recorder.</summary>
    private static string WriteTeleopGraphWithFilter(string repo, string folder)
    {
        Directory.CreateDirectory(folder);
        var graphs = Path.Combine(repo, "graphs");
        var graph = JsonNode.Parse(File.ReadAllText(Path.Combine(graphs, "teleop-lb.json")))!.AsObject();
        graph["robot"] = Path.GetFullPath(Path.Combine(graphs, (string)graph["robot"]!));
        var instances = graph["instances"]!.AsArray();
        foreach (var instance in instances)
        {
            if (instance!["settings"]?["script"] is { } script)
            {
                instance["settings"]!["script"] = Path.Combine(graphs, (string)script!);
            }
        }

        instances.Add(new JsonObject { ["name"] = "tremor_right", ["type"] = "mylab_filters_low_pass", ["settings"] = new JsonObject { ["cutoff_hz"] = 8 } });
        instances.Add(new JsonObject { ["name"] = "recorder", ["type"] = "recorder", ["settings"] = new JsonObject { ["path"] = "signals.csv" } });
        var wires = graph["wires"]!.AsArray();
        var wire = wires.Single(w => (string)w!["from"]! == "scaling_right.x" && (string)w!["to"]! == "clutch_right.x")!;
        wire["to"] = "tremor_right.in";
        wires.Add(new JsonObject { ["from"] = "tremor_right.out", ["to"] = "clutch_right.x" });

        var path = Path.Combine(folder, "teleop-lb-filtered.json");
        File.WriteAllText(path, graph.ToJsonString());
        return path;
    }

    /// <summary>
    /// The repository's package sources plus the test's local feeds, with RobotControl.* mapped to the local feeds only
    /// (so a same-named package elsewhere can never be picked).
    /// </summary>
    private static void WriteNuGetConfig(string path, string repoConfig, params string[] feeds)
    {
        var config = XDocument.Load(repoConfig);
        var sources = config.Root!.Element("packageSources")!;
        var mapping = new XElement("packageSourceMapping");
        foreach (var key in sources.Elements("add").Select(e => (string)e.Attribute("key")!))
        {
            mapping.Add(new XElement("packageSource", new XAttribute("key", key), new XElement("package", new XAttribute("pattern", "*"))));
        }

        for (var i = 0; i < feeds.Length; i++)
        {
            sources.Add(new XElement("add", new XAttribute("key", $"local{i}"), new XAttribute("value", feeds[i])));
            mapping.Add(new XElement("packageSource", new XAttribute("key", $"local{i}"), new XElement("package", new XAttribute("pattern", "RobotControl.*"))));
        }

        config.Root.Element("packageSourceMapping")?.Remove();
        config.Root.Add(mapping);
        config.Save(path);
    }

    private static void WriteSolution(string path, params string[] projects) =>
        File.WriteAllText(path, "<Solution>\n" + string.Concat(projects.Select(p => $"  <Project Path=\"{p}\" />\n")) + "</Solution>\n");

    private static void Copy(string from, string to)
    {
        if (File.Exists(from))
        {
            Directory.CreateDirectory(Path.GetDirectoryName(to)!);
            File.Copy(from, to);
            return;
        }

        foreach (var file in Directory.EnumerateFiles(from, "*", SearchOption.AllDirectories))
        {
            var relative = Path.GetRelativePath(from, file);
            if (relative.Split(Path.DirectorySeparatorChar).Any(part => part is "bin" or "obj") && !from.Contains("/bin/", StringComparison.Ordinal))
            {
                continue;
            }

            Directory.CreateDirectory(Path.GetDirectoryName(Path.Combine(to, relative))!);
            File.Copy(file, Path.Combine(to, relative));
        }
    }

    private static string RepoRoot()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            if (File.Exists(Path.Combine(dir.FullName, "RobotControl.sln")))
            {
                return dir.FullName;
            }
        }

        throw new InvalidOperationException("repository root (RobotControl.sln) not found");
    }
}
