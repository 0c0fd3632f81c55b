using RobotControl.Definitions.Model;
using RobotControl.Plugins.Sdk.Devices;

namespace RobotControl.Plugins.Sdk;

/// <summary>What the host gives a plug-in when it creates it.</summary>
/// <param name="InstanceName">The instance's name in the graph (no dots).</param>
/// <param name="Robot">The graph's robot, when the graph names one.</param>
/// <param name="Time">The loop's clock (virtual in tests and simulation).</param>
/// <param name="BaseDirectory">Directory that relative paths in settings resolve against (the graph file's).</param>
public sealed record PluginContext(string InstanceName, RobotDefinition? Robot, TimeProvider Time, string BaseDirectory)
{
    /// <summary>A context for a stand-alone plug-in (tests, tools): no robot, system clock, current directory.</summary>
    public static PluginContext Standalone(string instanceName, RobotDefinition? robot = null, TimeProvider? time = null) =>
        new(instanceName, robot, time ?? TimeProvider.System, Directory.GetCurrentDirectory());

    /// <summary>How the host opens a device's bytes from a transport string (null when it opens none, e.g. stand-alone).</summary>
    public Func<string, IByteSource>? DeviceOpener { get; init; }

    /// <summary>Opens the device <paramref name="transport"/> names (e.g. <c>serial:/dev/ttyUSB1?baud=9600</c>) through the host.</summary>
    /// <exception cref="InvalidOperationException">The host opens no devices.</exception>
    /// <exception cref="IOException">The device cannot be opened.</exception>
    public IByteSource OpenDevice(string transport)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(transport);
        return DeviceOpener?.Invoke(transport)
            ?? throw new InvalidOperationException($"plug-in instance '{InstanceName}': this host opens no devices (transport '{transport}')");
    }

    /// <summary>Resolves a path from settings against <see cref="BaseDirectory"/>.</summary>
    public string ResolvePath(string path)
    {
        ArgumentException.ThrowIfNullOrEmpty(path);
        return Path.GetFullPath(Path.IsPathRooted(path) ? path : Path.Combine(BaseDirectory, path));
    }

    /// <summary>The robot, or an exception naming the instance when the graph has none.</summary>
    /// <exception cref="InvalidOperationException">The graph names no robot.</exception>
    public RobotDefinition RequireRobot() =>
        Robot ?? throw new InvalidOperationException($"plug-in instance '{InstanceName}' needs the graph to name a robot file");
}
