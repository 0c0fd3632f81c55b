using RobotControl.Bus.Transports;
using RobotControl.Hardware.Model;
using RobotControl.Host.Harness;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// Faults injected into a virtual console session (<c>robotctl console --virtual --inject silent=left.forearm@5s</c>):
/// the <c>silent=</c> form of <c>robotctl run --inject</c> (a module's replies stop reaching the host), timed from the
/// start of the session. The other forms need the harness's run loop and are refused with one line.
/// </summary>
#pragma warning disable CA1001 // the link it wraps is the session's: the session layer disposes it with the bus
internal sealed class ConsoleFaults
#pragma warning restore CA1001
{
    private readonly FaultInjection _inject;
    private SilentModuleLink? _link;

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

    /// <summary>The link wrapper for the session layer, or null when nothing is injected.</summary>
    public Func<IByteLink, TimeProvider, IByteLink>? WrapLink => _inject.IsNone ? null : (link, clock) => _link = new SilentModuleLink(link, clock);

    /// <summary>Schedules the faults from <paramref name="begin"/> (a timestamp of the bus clock) on.</summary>
    /// <exception cref="FormatException">A fault names no module of <paramref name="robot"/>.</exception>
    public void Schedule(RobotDefinition robot, long begin, long frequency)
    {
        foreach (var f in _inject.TimedFaults)
        {
            _link!.Silence(HeadlessRun.ResolveModule(robot, f.Target), begin + (long)(f.At.TotalSeconds * frequency));
        }
    }
}
