using RobotControl.Definitions.Model;
using RobotControl.Host.Harness;
using RobotControl.Simulation;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// Faults injected into a virtual console session (<c>robotctl console --virtual --inject silent=left.forearm@5s</c>):
/// the <c>silent=</c> form of <c>robotctl run --inject</c> (the module's transmit line breaks inside the virtual robot:
/// its replies stop reaching the host), timed from the start of the session. The other forms need the harness's run
/// loop and are refused with one line.
/// </summary>
internal sealed class ConsoleFaults
{
    private readonly FaultInjection _inject;

    /// <summary>Checks <paramref name="inject"/>: only <c>silent=</c> faults, and only on the virtual robot.</summary>
    /// <exception cref="FormatException">Another form, or a real bus.</exception>
    public ConsoleFaults(FaultInjection inject, bool isVirtual)
    {
        ArgumentNullException.ThrowIfNull(inject);
        if (!inject.IsNone && !isVirtual)
        {
            throw new FormatException("--inject: faults are injected into the virtual robot only (add --virtual)");
        }

        if (inject.BitErrorRate > 0 || inject.Resets.Count > 0 || inject.TimedFaults.Any(f => f.Kind != TimedFaultKind.Silent))
        {
            throw new FormatException($"--inject '{inject}': the console injects silent=<module>@<time> only (robotctl run takes the other forms)");
        }

        _inject = inject;
    }

    /// <summary>Schedules the faults in <paramref name="sim"/> (null on a real bus, where nothing is injected), timed from now.</summary>
    /// <exception cref="FormatException">A fault names no module of <paramref name="robot"/>.</exception>
    public void Schedule(VirtualRobot? sim, RobotDefinition robot)
    {
        foreach (var f in _inject.TimedFaults)
        {
            sim!.ScheduleTransmitBreak(HeadlessRun.ResolveModule(robot, f.Target), sim.Elapsed + f.At);
        }
    }
}
