using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Standard.Haptics;

/// <summary>Settings of <see cref="ViscousDampingPlugin"/>.</summary>
public sealed record ViscousDampingSettings : PluginSettings
{
    /// <summary>Damping coefficient b.</summary>
    [Setting("Damping b: force per handle speed (F = -b v).", Units = "N s/mm", Minimum = 0, Maximum = 0.1)]
    public double DampingNsPerMm { get; init; } = 0.002;

    /// <summary>Cut-off of the velocity filter.</summary>
    [Setting("Cut-off of the first-order filter on the differentiated handle velocity.", Units = "Hz", Minimum = 1, Maximum = 500)]
    public double VelocityFilterHz { get; init; } = 30;

    /// <summary>Per-axis clamp of the damping force.</summary>
    [Setting("Largest damping force per axis.", Units = "N", Minimum = 0, Maximum = 10)]
    public double MaxForceN { get; init; } = 1.0;
}
