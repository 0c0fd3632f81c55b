namespace RobotControl.Plugins.Sdk.Faults;

/// <summary>
/// Implemented by a plug-in whose device can have faults injected (a simulated input device): the harness's
/// <c>robotctl run --inject jump=touch_right:50mm@5s</c> and <c>stale=touch_right@5s</c> find the instance by name
/// in the loaded graph, ask <see cref="CanTake"/>, and call <see cref="Inject"/> at the fault's time. A fault aimed
/// at an instance that does not implement this, or cannot take that kind, is refused before the first tick.
/// </summary>
public interface IFaultInjectable
{
    /// <summary>True when this instance can take faults of <paramref name="kind"/> now (a plug-in on a real device may take none).</summary>
    bool CanTake(DeviceFaultKind kind);

    /// <summary>
    /// Applies <paramref name="fault"/> from the next tick on. Called on the loop thread between ticks, once per fault,
    /// only with a kind <see cref="CanTake"/> accepts.
    /// </summary>
    /// <exception cref="ArgumentException">This instance cannot take the fault (its kind, or a jump that is not finite).</exception>
    void Inject(DeviceFault fault);
}
