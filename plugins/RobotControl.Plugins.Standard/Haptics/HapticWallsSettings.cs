using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Standard.Haptics;

/// <summary>
/// Settings of <see cref="HapticWallsPlugin"/>. The device-frame fields must match the homing and scaling instances
/// of the same arm: the walls undo them to express the workspace force in the device frame.
/// </summary>
public sealed record HapticWallsSettings : PluginSettings
{
    /// <summary>Homing roll (as in the arm's homing instance).</summary>
    [Setting("Homing roll of this arm's device (as in its homing instance).", Units = "deg", Minimum = -180, Maximum = 180)]
    public double RollDeg { get; init; }

    /// <summary>Homing pitch.</summary>
    [Setting("Homing pitch (as in the homing instance).", Units = "deg", Minimum = -180, Maximum = 180)]
    public double PitchDeg { get; init; }

    /// <summary>Homing yaw.</summary>
    [Setting("Homing yaw (as in the homing instance).", Units = "deg", Minimum = -180, Maximum = 180)]
    public double YawDeg { get; init; }

    /// <summary>Homing x inversion.</summary>
    [Setting("Homing x inversion (as in the homing instance).")]
    public bool InvertX { get; init; }

    /// <summary>Homing y inversion.</summary>
    [Setting("Homing y inversion (as in the homing instance).")]
    public bool InvertY { get; init; }

    /// <summary>Homing z inversion.</summary>
    [Setting("Homing z inversion (as in the homing instance).")]
    public bool InvertZ { get; init; }

    /// <summary>Homing mirror (left arm).</summary>
    [Setting("Homing mirror (as in the homing instance; set for the left arm).")]
    public bool Mirror { get; init; }

    /// <summary>Scaling ratio of the arm (device displacement is robot displacement / ratio).</summary>
    [Setting("Scaling ratio of this arm until the scale_ratio input says otherwise (graphs wire the scaling's ratio output to it): the spring acts on device displacement.", Minimum = 0.01, Maximum = 10)]
    public double ScaleRatio { get; init; } = 1.0;

    /// <summary>Extra gain on the force.</summary>
    [Setting("Gain applied to the workspace force.", Minimum = 0, Maximum = 100)]
    public double Gain { get; init; } = 1.0;

    /// <summary>Per-axis clamp of the device force.</summary>
    [Setting("Largest force per device axis.", Units = "N", Minimum = 0, Maximum = 10)]
    public double MaxForceN { get; init; } = 2.0;

    /// <summary>Invert the x force (device frames differ).</summary>
    [Setting("Invert the force along device x (the reference design's per-axis sign setting).")]
    public bool InvertForceX { get; init; }

    /// <summary>Invert the y force.</summary>
    [Setting("Invert the force along device y.")]
    public bool InvertForceY { get; init; }

    /// <summary>Invert the z force.</summary>
    [Setting("Invert the force along device z.")]
    public bool InvertForceZ { get; init; }
}
