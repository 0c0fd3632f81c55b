using System.CommandLine;
using System.Text.Json;
using RobotControl.Cli.Commands.Run;
using RobotControl.Hardware.Loading;
using RobotControl.Hardware.Model;
using RobotControl.Plugins.Sdk;

namespace RobotControl.Cli.Commands.Plugins;

/// <summary>
/// <c>robotctl plugins [--plugins dir] [--robot file] [--json]</c>: every plug-in type the host finds (its own and a
/// plug-ins folder's): name, description, inputs and outputs with units, settings with ranges, assembly and the SDK
/// version it was built against. A table for people, JSON for scripts.
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
        var command = new Command("plugins", "List the plug-in types found: ports with units, settings with ranges, assembly and SDK version.");
        command.Options.Add(plugins);
        command.Options.Add(robot);
        command.Options.Add(json);
        command.SetAction(parse => Run(
            parse.GetValue(plugins)?.FullName,
            parse.GetValue(robot)?.FullName,
            parse.GetValue(json),
            parse.InvocationConfiguration.Output,
            parse.InvocationConfiguration.Error));
        return command;
    }

    /// <summary>Runs the command; returns 0, or 2 when the folder or robot file is unusable.</summary>
    internal static int Run(string? pluginsFolder, string? robotPath, bool json, TextWriter output, TextWriter error)
    {
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

        var catalog = RunCommand.Catalog(pluginsFolder);
        foreach (var problem in catalog.Problems)
        {
            error.WriteLine($"plug-ins: {problem}");
        }

        var listings = catalog.Types.OrderBy(t => t.Name, StringComparer.Ordinal).Select(t => PluginListing.Of(t, robot)).ToList();
        if (json)
        {
            output.WriteLine(JsonSerializer.Serialize(new { host_sdk_version = SdkVersion.Text, plugins = listings, problems = catalog.Problems }, Json));
        }
        else
        {
            PluginListingText.Write(listings, output);
        }

        return 0;
    }
}
