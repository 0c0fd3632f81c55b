using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Touch;

/// <summary>Which back end a Touch instance uses.</summary>
public enum TouchBackendKind
{
    /// <summary>A scripted hand holding a simulated stylus.</summary>
    Simulated,
}

/// <summary>Settings of <see cref="TouchPlugin"/>.</summary>
public sealed record TouchSettings : PluginSettings
{
    /// <summary>The back end.</summary>
    [Setting("Back end: simulated (scripted hand). The OpenHaptics device is a planned second back end.")]
    public TouchBackendKind Backend { get; init; } = TouchBackendKind.Simulated;

    /// <summary>The hand script (CSV), relative to the graph file.</summary>
    [Setting("Hand trajectory script (CSV: time_s,x_mm,y_mm,z_mm[,roll_rad,pitch_rad,yaw_rad,button1,button2]).", IsFilePath = true, Required = true)]
    public string Script { get; init; } = "";

    /// <summary>Column prefix when the script is a recording.</summary>
    [Setting("Read the script from a recording instead: the prefix of the recorded Touch's columns, e.g. touch_right. (empty: a hand script).")]
    public string RecordingPrefix { get; init; } = "";

    /// <summary>Start the script this far in.</summary>
    [Setting("Start the script this far in.", Units = "s", Minimum = 0, Maximum = 86400)]
    public double TimeOffsetS { get; init; }

    /// <summary>Repeat the script when it ends.</summary>
    [Setting("Repeat the script when it ends (otherwise the hand rests at the last keyframe).")]
    public bool Repeat { get; init; }

    /// <summary>Effective mass of hand and stylus.</summary>
    [Setting("Hand model: effective mass of hand and stylus.", Units = "kg", Minimum = 0.01, Maximum = 5)]
    public double HandMassKg { get; init; } = 0.25;

    /// <summary>Grip stiffness of the hand model.</summary>
    [Setting("Hand model: grip stiffness (how hard the hand holds the stylus on its path).", Units = "N/mm", Minimum = 0.01, Maximum = 5)]
    public double HandStiffnessNPerMm { get; init; } = 0.2;

    /// <summary>Grip damping of the hand model.</summary>
    [Setting("Hand model: grip damping.", Units = "N s/mm", Minimum = 0, Maximum = 1)]
    public double HandDampingNsPerMm { get; init; } = 0.01;

    /// <summary>Largest force the device renders (the Touch's peak is 3.3 N).</summary>
    [Setting("Largest force the device renders (the Touch's nominal peak is 3.3 N).", Units = "N", Minimum = 0, Maximum = 10)]
    public double MaxForceN { get; init; } = 3.3;
}
