using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Standard.Conditioning;

/// <summary>Settings of <see cref="ClutchPlugin"/>.</summary>
public sealed record ClutchSettings : PluginSettings
{
    /// <summary>The clutch input value at or above which the clutch is engaged.</summary>
    [Setting("Clutch input at or above which the clutch is held (buttons and pedals give 0 or 1).", Minimum = -1000, Maximum = 1000)]
    public double Threshold { get; init; } = 0.5;

    /// <summary>Engage when the input is below the threshold instead (a dead-man switch: release to clutch).</summary>
    [Setting("Engage when the input is below the threshold (dead-man style) instead of at or above it.")]
    public bool Inverted { get; init; }
}
