using System.CommandLine;
using System.Text.Json;
using RobotControl.Cli.Commands.Run;
using RobotControl.Definitions.Loading;
using RobotControl.Definitions.Model;
using RobotControl.Plugins.Sdk;
using RobotControl.Runtime.Discovery;

namespace RobotControl.Cli.Commands.Plugins;

/// <summary>
/// <c>robotctl plugins [--plugins dir] [--robot file] [--json | --markdown]</c>: every plug-in type the host finds (its
/// own and a plug-ins folder's): name, description, inputs and outputs with units, settings with ranges, assembly and
/// the SDK version it was built against. A table for people, JSON for scripts, Markdown for the reference in docs/.
/// </summary>
internal sealed class PluginsCommand : ICliCommand
{
    private static readonly JsonSerializerOptions Json = new()
    {
        PropertyNamingPolicy = JsonNamingPolicy.SnakeCaseLower,
        WriteIndented = true,
        DefaultIgnoreCondition = System.Text.Json.Serialization.JsonIgnoreCondition.WhenWritingNull,
    };

    /// <inheritdoc />
    public Command Build()
    {
        var plugins = new Option<DirectoryInfo?>("--plugins") { Description = "Also load plug-in assemblies from this folder (as robotctl run does)" };
        var robot = new Option<FileInfo?>("--robot") { Description = "Robot file to create the plug-ins with, for plug-ins whose ports depend on the robot (e.g. one per joint)" };
        var json = new Option<bool>("--json") { Description = "Write JSON (for scripts) instead of the table" };
        var markdown = new Option<bool>("--markdown") { Description = "Write the Markdown reference (docs/plugin-reference.md) instead of the table" };
        var examples = new Option<FileInfo?>("--examples") { Description = "Graph file whose instances' settings describe the types whose defaults cannot make an instance (e.g. a simulated touch without a script)" };
        var command = new Command("plugins", "List the plug-in types found: ports with units, settings with ranges, assembly and SDK version.");
        command.Options.Add(plugins);
        command.Options.Add(robot);
        command.Options.Add(json);
        command.Options.Add(markdown);
        command.Options.Add(examples);
        command.SetAction(parse => Run(
            parse.GetValue(plugins)?.FullName,
            parse.GetValue(robot)?.FullName,
            parse.GetValue(examples)?.FullName,
            Format(parse.GetValue(json), parse.GetValue(markdown)),
            parse.InvocationConfiguration.Output,
            parse.InvocationConfiguration.Error));
        return command;
    }

    /// <summary>Runs the command; returns 0, or 2 when the folder or robot file is unusable or both formats are asked.</summary>
    internal static int Run(string? pluginsFolder, string? robotPath, PluginsFormat format, TextWriter output, TextWriter error) =>
        Run(pluginsFolder, robotPath, null, format, output, error);

    /// <summary>As above, with a graph file whose instances describe the types whose defaults cannot make one.</summary>
    internal static int Run(string? pluginsFolder, string? robotPath, string? examplesGraph, PluginsFormat format, TextWriter output, TextWriter error)
    {
        if (format == PluginsFormat.Conflicting)
        {
            error.WriteLine("--json and --markdown: give one of them");
            return 2;
        }

        if (pluginsFolder is not null && !Directory.Exists(pluginsFolder))
        {
            error.WriteLine($"--plugins: folder '{pluginsFolder}' does not exist");
            return 2;
        }

        RobotDefinition? robot = null;
        if (robotPath is not null)
        {
            try
            {
                robot = RobotLoader.Load(robotPath);
            }
            catch (RobotDataException ex)
            {
                error.WriteLine(ex.Message);
                return 2;
            }
        }

        var catalog = ShippedPlugins.Catalog(pluginsFolder);
        Dictionary<string, PluginExample> examples = [];
        if (examplesGraph is not null)
        {
            try
            {
                examples = PluginExample.FromGraph(examplesGraph, catalog);
            }
            catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or System.Text.Json.JsonException)
            {
                error.WriteLine($"--examples: {examplesGraph}: {ex.Message.Split('\n')[0].Trim()}");
                return 2;
            }
        }

        foreach (var problem in catalog.Problems)
        {
            error.WriteLine($"plug-ins: {problem}");
        }

        var listings = catalog.Types
            .OrderBy(t => t.Name, StringComparer.Ordinal)
            .Select(t => PluginDescription.Of(t, robot, Directory.GetCurrentDirectory(), examples.GetValueOrDefault(t.Name)))
            .ToList();
        switch (format)
        {
            case PluginsFormat.Json:
                output.WriteLine(JsonSerializer.Serialize(new { host_sdk_version = SdkVersion.Text, plugins = listings, problems = catalog.Problems }, Json));
                break;
            case PluginsFormat.Markdown:
                output.Write(PluginReference.Document(listings, robot?.Name));
                break;
            default:
                PluginListingText.Write(listings, output);
                break;
        }

        return 0;
    }

    private static PluginsFormat Format(bool json, bool markdown) => (json, markdown) switch
    {
        (true, true) => PluginsFormat.Conflicting,
        (true, false) => PluginsFormat.Json,
        (false, true) => PluginsFormat.Markdown,
        _ => PluginsFormat.Table,
    };
}
