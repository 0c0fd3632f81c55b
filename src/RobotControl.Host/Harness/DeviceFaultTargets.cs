using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Faults;

namespace RobotControl.Host.Harness;

/// <summary>
/// Where the device faults of <c>--inject</c> (<c>jump=</c>, <c>stale=</c>) go: the graph instance they name, through
/// the SDK's <see cref="IFaultInjectable"/> seam. The harness knows no plug-in type; an instance takes a fault when
/// it implements the seam and says it can take that kind. <c>robotctl run</c> checks the targets before anything
/// starts; the run's fault schedule resolves them again on the session's own graph.
/// </summary>
public static class DeviceFaultTargets
{
    /// <summary>True for the faults that go to a plug-in instance (<c>jump=</c>, <c>stale=</c>).</summary>
    public static bool IsDeviceFault(TimedFault fault)
    {
        ArgumentNullException.ThrowIfNull(fault);
        return fault.Kind is TimedFaultKind.Jump or TimedFaultKind.Stale;
    }

    /// <summary>The device fault <paramref name="fault"/> injects.</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="fault"/> is not a device fault.</exception>
    public static DeviceFault FaultOf(TimedFault fault)
    {
        ArgumentNullException.ThrowIfNull(fault);
        return fault.Kind switch
        {
            TimedFaultKind.Jump => DeviceFault.Jump(fault.JumpMm),
            TimedFaultKind.Stale => DeviceFault.Stale,
            _ => throw new ArgumentOutOfRangeException(nameof(fault), fault.Kind, "not a device fault"),
        };
    }

    /// <summary>The instance of <paramref name="instances"/> that <paramref name="fault"/> names, able to take it.</summary>
    /// <exception cref="FormatException">No instance of that name, or it cannot take the fault (one line naming the fault and the instance, and listing those that can).</exception>
    public static IFaultInjectable Resolve(TimedFault fault, IReadOnlyList<Plugin> instances)
    {
        ArgumentNullException.ThrowIfNull(fault);
        ArgumentNullException.ThrowIfNull(instances);
        var kind = FaultOf(fault).Kind;
        var name = kind.ToString().ToLowerInvariant();
        var able = string.Join(", ", instances.Where(p => p is IFaultInjectable i && i.CanTake(kind)).Select(p => p.Name));
        var target = instances.FirstOrDefault(p => p.Name == fault.Target)
            ?? throw new FormatException($"--inject '{fault}': no plug-in '{fault.Target}' in the graph (plug-ins that take {name} faults: {Listed(able)})");
        return target is IFaultInjectable injectable && injectable.CanTake(kind)
            ? injectable
            : throw new FormatException($"--inject '{fault}': plug-in '{fault.Target}' cannot take {name} faults (plug-ins that take them: {Listed(able)})");
    }

    private static string Listed(string names) => names.Length == 0 ? "none" : names;
}
