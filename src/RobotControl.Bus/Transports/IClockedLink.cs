namespace RobotControl.Bus.Transports;

/// <summary>
/// A link whose time is simulated (the virtual bus): clients must measure timeouts and latencies on
/// <see cref="Clock"/>, which moves as the simulation runs.
/// </summary>
public interface IClockedLink
{
    /// <summary>The link's clock.</summary>
    TimeProvider Clock { get; }
}
