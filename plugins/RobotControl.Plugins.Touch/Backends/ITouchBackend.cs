namespace RobotControl.Plugins.Touch.Backends;

/// <summary>
/// Where a Touch plug-in's samples come from and its forces go. The simulated back end computes both on the loop
/// thread from the tick time (deterministic); the OpenHaptics back end runs its 1 kHz servo callback on the driver's
/// thread and exchanges the latest sample and force with the loop through <see cref="Sdk.Exchange.LatestValue{T}"/>,
/// so <see cref="Exchange"/> never blocks.
/// </summary>
public interface ITouchBackend : IDisposable
{
    /// <summary>What the back end is, for messages.</summary>
    string Description { get; }

    /// <summary>Opens the device (called from the plug-in's Start).</summary>
    void Open();

    /// <summary>Hands over the force to render and returns the latest sample for loop time <paramref name="timeSeconds"/>. Non-blocking, allocation-free.</summary>
    TouchSample Exchange(double timeSeconds, in TouchForce force);
}
