using RobotControl.Hardware.Model;

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
