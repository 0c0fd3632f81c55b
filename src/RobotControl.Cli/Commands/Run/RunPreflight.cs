using System.Globalization;
using RobotControl.Bus.Transports;
using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.GraphFiles;
using RobotControl.Host.Harness;
using RobotControl.Simulation.Time;

namespace RobotControl.Cli.Commands.Run;

/// <summary>
/// What <c>robotctl run</c> checks before it starts anything: the graph loads, and when it names a robot file (a graph
/// without one is a station, run on the wall clock without a robot), that file has a modules section (the bus, virtual or real, is made of them), the graph's transport is well-formed even when
/// <c>--virtual</c> replaces it, every injected fault falls inside the run, and every device fault names an instance
/// of the graph that can take it.
/// </summary>
internal static class RunPreflight
{
    /// <summary>Checks <paramref name="options"/>; false when the graph names no robot (a station of a split graph, <see cref="Host.Station.StationRun"/>).</summary>
    /// <exception cref="FormatException">A check failed (the message says which and why).</exception>
    /// <exception cref="Runtime.Graph.GraphException">The graph file is invalid.</exception>
    public static bool Check(RunOptions options, PluginCatalog catalog)
    {
        ArgumentNullException.ThrowIfNull(options);
        ArgumentNullException.ThrowIfNull(catalog);
        var loaded = GraphFile.Load(options.GraphPath, catalog, new ManualTimeProvider());
        if (loaded.Robot is not { } robot)
        {
            return false; // the station run says which options it cannot take
        }

        if (robot.Modules.Modules.Count == 0)
        {
            throw new FormatException($"{loaded.Path}: its robot file {robot.SourceFile} has no modules section; a run needs the robot's bus modules (ids, channels, gains), virtual or real");
        }

        var transport = loaded.Document.Transport;
        if (!transport.Equals("virtual", StringComparison.OrdinalIgnoreCase))
        {
            try
            {
                LinkUri.Parse(transport);
            }
            catch (FormatException ex)
            {
                throw new FormatException($"{loaded.Path}: $.transport: {ex.Message}", ex);
            }
        }

        foreach (var reset in options.Inject.Resets.Where(r => r.At > options.Duration))
        {
            throw new FormatException(string.Create(
                CultureInfo.InvariantCulture,
                $"--inject reset={reset.Module}@{reset.At.TotalSeconds:0.###}s: after the end of the run ({options.Duration.TotalSeconds:0.###} s), so it would never happen"));
        }

        foreach (var fault in options.Inject.TimedFaults.Where(DeviceFaultTargets.IsDeviceFault))
        {
            DeviceFaultTargets.Resolve(fault, loaded.Program.Order);
        }

        return true;
    }
}
