using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Standard.Conditioning;

/// <summary>Settings of <see cref="ScalingPlugin"/>.</summary>
public sealed record ScalingSettings : PluginSettings
{
    /// <summary>Motion ratio: output displacement per input displacement.</summary>
    [Setting("Output displacement per input displacement from the reference point (0.2-1.0 for fine motion).", Minimum = 0.01, Maximum = 10)]
    public double Ratio { get; init; } = 0.5;

    /// <summary>Reference point x (displacements are measured from it).</summary>
    [Setting("Reference point x: displacements are scaled about it.", Units = "mm", Minimum = -1000, Maximum = 1000)]
    public double ReferenceXMm { get; init; }

    /// <summary>Reference point y.</summary>
    [Setting("Reference point y.", Units = "mm", Minimum = -1000, Maximum = 1000)]
    public double ReferenceYMm { get; init; }

    /// <summary>Reference point z.</summary>
    [Setting("Reference point z.", Units = "mm", Minimum = -1000, Maximum = 1000)]
    public double ReferenceZMm { get; init; }
}
