using RobotControl.Plugins.Sdk.Settings;

namespace MyLab.Filters;

/// <summary>Settings of <see cref="LowPassPlugin"/>; graph files name them in snake_case (<c>cutoff_hz</c>).</summary>
public sealed record LowPassSettings : PluginSettings
{
    /// <summary>The -3 dB frequency of the filter.</summary>
    [Setting("Cut-off (-3 dB) frequency of the first-order low-pass filter.", Units = "Hz", Minimum = 0.1, Maximum = 200)]
    public double CutoffHz { get; init; } = 5;
}
