using System.Text.Json;
using RobotControl.Definitions.Model;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Runtime.Discovery;

/// <summary>An instance's inputs and outputs, in port order.</summary>
/// <param name="Inputs">Its inputs.</param>
/// <param name="Outputs">Its outputs.</param>
public sealed record PluginPorts(IReadOnlyList<PortDescription> Inputs, IReadOnlyList<PortDescription> Outputs)
{
    private const string ProbeName = "probe";

    /// <summary>The ports <paramref name="plugin"/> declared.</summary>
    public static PluginPorts Of(Plugin plugin)
    {
        ArgumentNullException.ThrowIfNull(plugin);
        return new PluginPorts(
            [.. plugin.Inputs.Select(p => PortDescription.Of(p, isOutput: false))],
            [.. plugin.Outputs.Select(p => PortDescription.Of(p, isOutput: true))]);
    }

    /// <summary>
    /// Creates an instance of <paramref name="type"/> with <paramref name="settings"/> (null: the defaults) on
    /// <paramref name="robot"/>, takes its ports and disposes it. The instance opens no device. A type whose ports
    /// depend on its settings or on a robot may fail to be created: <paramref name="problem"/> then says why.
    /// </summary>
    public static bool TryCreate(PluginTypeInfo type, PluginSettings? settings, RobotDefinition? robot, string baseDirectory, out PluginPorts? ports, out string? problem)
    {
        ArgumentNullException.ThrowIfNull(type);
        ports = null;
        problem = null;
        try
        {
            var context = new PluginContext(ProbeName, robot, TimeProvider.System, baseDirectory);
            var plugin = type.Create(settings, context);
            ports = Of(plugin);
            (plugin as IDisposable)?.Dispose();
            return true;
        }
        catch (SettingsException ex)
        {
            problem = Problem(settings, robot, string.Join("; ", ex.Errors.Select(e => $"{e.Path}: {e.Message}")));
        }
#pragma warning disable CA1031 // a plug-in constructor may fail in any way; the description says so instead of failing
        catch (Exception ex) when (ex is not OutOfMemoryException)
#pragma warning restore CA1031
        {
            problem = Problem(settings, robot, ex.Message);
        }

        return false;
    }

    private static string Problem(PluginSettings? settings, RobotDefinition? robot, string why) =>
        $"declared when created; with {(settings is null ? "default settings" : "these settings")}{(robot is null ? " and no robot" : "")}: {why}";
}

/// <summary>One input or output.</summary>
/// <param name="Name">Port name (the signal is <c>instance.port</c>).</param>
/// <param name="Units">Units (empty when none).</param>
/// <param name="Description">What it carries.</param>
/// <param name="InitialValue">Its value before the first tick.</param>
/// <param name="SafeValue">For an output, what it becomes when its plug-in faults (<c>hold_last_finite</c>, <c>zero</c> or <c>initial</c>); null for an input.</param>
public sealed record PortDescription(string Name, string Units, string Description, double InitialValue, string? SafeValue)
{
    /// <summary>Describes <paramref name="port"/>.</summary>
    public static PortDescription Of(PortInfo port, bool isOutput)
    {
        ArgumentNullException.ThrowIfNull(port);
        return new(port.Name, port.Units, port.Description, port.InitialValue, isOutput ? JsonNamingPolicy.SnakeCaseLower.ConvertName(port.SafeValue.ToString()) : null);
    }
}
