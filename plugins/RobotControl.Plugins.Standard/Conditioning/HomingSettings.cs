using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Standard.Conditioning;

/// <summary>Settings of <see cref="HomingPlugin"/>: the rigid transform from the device frame to the arm's base frame.</summary>
public sealed record HomingSettings : PluginSettings
{
    /// <summary>Robot-frame x of the point the device's origin maps to.</summary>
    [Setting("Robot-frame x of the point the device's home point maps to.", Units = "mm", Minimum = -1000, Maximum = 1000)]
    public double OriginXMm { get; init; }

    /// <summary>Robot-frame y of the point the device's origin maps to.</summary>
    [Setting("Robot-frame y of the point the device's home point maps to.", Units = "mm", Minimum = -1000, Maximum = 1000)]
    public double OriginYMm { get; init; }

    /// <summary>Robot-frame z of the point the device's origin maps to.</summary>
    [Setting("Robot-frame z of the point the device's home point maps to.", Units = "mm", Minimum = -1000, Maximum = 1000)]
    public double OriginZMm { get; init; }

    /// <summary>Device-frame x of the device's home point.</summary>
    [Setting("Device-frame x of the device's home point.", Units = "mm", Minimum = -1000, Maximum = 1000)]
    public double DeviceHomeXMm { get; init; }

    /// <summary>Device-frame y of the device's home point.</summary>
    [Setting("Device-frame y of the device's home point.", Units = "mm", Minimum = -1000, Maximum = 1000)]
    public double DeviceHomeYMm { get; init; }

    /// <summary>Device-frame z of the device's home point.</summary>
    [Setting("Device-frame z of the device's home point.", Units = "mm", Minimum = -1000, Maximum = 1000)]
    public double DeviceHomeZMm { get; init; }

    /// <summary>Roll of the device frame in the robot frame (about x, applied first).</summary>
    [Setting("Roll of the device frame in the robot frame (about x, applied first).", Units = "deg", Minimum = -180, Maximum = 180)]
    public double RollDeg { get; init; }

    /// <summary>Pitch of the device frame in the robot frame (about y).</summary>
    [Setting("Pitch of the device frame in the robot frame (about y).", Units = "deg", Minimum = -180, Maximum = 180)]
    public double PitchDeg { get; init; }

    /// <summary>Yaw of the device frame in the robot frame (about z, applied last).</summary>
    [Setting("Yaw of the device frame in the robot frame (about z, applied last).", Units = "deg", Minimum = -180, Maximum = 180)]
    public double YawDeg { get; init; }

    /// <summary>Invert the device's x axis before rotating.</summary>
    [Setting("Invert the device's x axis before rotating.")]
    public bool InvertX { get; init; }

    /// <summary>Invert the device's y axis before rotating.</summary>
    [Setting("Invert the device's y axis before rotating.")]
    public bool InvertY { get; init; }

    /// <summary>Invert the device's z axis before rotating.</summary>
    [Setting("Invert the device's z axis before rotating.")]
    public bool InvertZ { get; init; }

    /// <summary>Mirror in the robot's mirror plane (x-z): the left arm shares the right arm's model.</summary>
    [Setting("Mirror in the robot's x-z plane (y -> -y): set for the left arm, which shares the right arm's kinematic model.")]
    public bool Mirror { get; init; }
}
