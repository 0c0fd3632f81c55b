using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Standard.Haptics;

/// <summary>Settings of <see cref="HapticLockPlugin"/>.</summary>
public sealed record HapticLockSettings : PluginSettings
{
    /// <summary>Stiffness of the spring to the lock point.</summary>
    [Setting("Stiffness of the spring that holds the handle at the lock point.", Units = "N/mm", Minimum = 0, Maximum = 5)]
    public double StiffnessNPerMm { get; init; } = 0.5;

    /// <summary>Lock input at or above which the lock is on.</summary>
    [Setting("Lock input at or above which the lock is on (buttons and pedals give 0 or 1).", Minimum = -1000, Maximum = 1000)]
    public double Threshold { get; init; } = 0.5;

    /// <summary>Per-axis clamp of the lock force.</summary>
    [Setting("Largest lock force per axis.", Units = "N", Minimum = 0, Maximum = 10)]
    public double MaxForceN { get; init; } = 3.0;
}
