using RobotControl.Definitions.Json;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Touch;

/// <summary>Which back end a Touch instance uses.</summary>
public enum TouchBackendKind
{
    /// <summary>A scripted hand holding a simulated stylus.</summary>
    Simulated,

    /// <summary>A Geomagic Touch through the OpenHaptics HD API (libHD.so / HD.dll).</summary>
    Openhaptics,
}

/// <summary>Settings of <see cref="TouchPlugin"/>.</summary>
public sealed record TouchSettings : PluginSettings
{
    /// <summary>The back end.</summary>
    [Setting("Back end: simulated (scripted hand) or openhaptics (a Geomagic Touch through the OpenHaptics HD API).")]
    public TouchBackendKind Backend { get; init; } = TouchBackendKind.Simulated;

    /// <summary>The OpenHaptics device name (one instance per device).</summary>
    [Setting("openhaptics: the device's name as configured in Touch Setup, e.g. right (empty: the default device). Two devices in one graph are two instances with different names.")]
    public string Device { get; init; } = "";

    /// <summary>Where the HD library is.</summary>
    [Setting("openhaptics: the HD library (libHD.so / HD.dll) or the folder holding it (empty: LD_LIBRARY_PATH, then the system's library path).", IsFilePath = true)]
    public string LibraryPath { get; init; } = "";

    /// <summary>Time over which force is ramped in when force output starts.</summary>
    [Setting("openhaptics: force is ramped in over this time whenever force output starts (after start-up, a stale loop or force_enable going to 1).", Units = "s", Minimum = 0, Maximum = 5)]
    public double ForceRampS { get; init; } = 0.25;

    /// <summary>Age after which the loop's force is stale.</summary>
    [Setting("openhaptics: the device sends zero force when the loop has not handed over a force for this long.", Units = "ms", Minimum = 2, Maximum = 1000)]
    public double StaleAfterMs { get; init; } = 10;

    /// <summary>The hand script (CSV), relative to the graph file.</summary>
    [Setting("simulated: hand trajectory script (CSV: time_s,x_mm,y_mm,z_mm[,roll_rad,pitch_rad,yaw_rad,button1,button2]).", IsFilePath = true)]
    public string Script { get; init; } = "";

    /// <summary>Column prefix when the script is a recording.</summary>
    [Setting("simulated: read the script from a recording instead: the prefix of the recorded Touch's columns, e.g. touch_right. (empty: a hand script).")]
    public string RecordingPrefix { get; init; } = "";

    /// <summary>Start the script this far in.</summary>
    [Setting("simulated: start the script this far in.", Units = "s", Minimum = 0, Maximum = 86400)]
    public double TimeOffsetS { get; init; }

    /// <summary>Repeat the script when it ends.</summary>
    [Setting("simulated: repeat the script when it ends (otherwise the hand rests at the last keyframe).")]
    public bool Repeat { get; init; }

    /// <summary>Effective mass of hand and stylus.</summary>
    [Setting("simulated: hand model: effective mass of hand and stylus.", Units = "kg", Minimum = 0.01, Maximum = 5)]
    public double HandMassKg { get; init; } = 0.25;

    /// <summary>Grip stiffness of the hand model.</summary>
    [Setting("simulated: hand model: grip stiffness (how hard the hand holds the stylus on its path).", Units = "N/mm", Minimum = 0.01, Maximum = 5)]
    public double HandStiffnessNPerMm { get; init; } = 0.2;

    /// <summary>Grip damping of the hand model.</summary>
    [Setting("simulated: hand model: grip damping.", Units = "N s/mm", Minimum = 0, Maximum = 1)]
    public double HandDampingNsPerMm { get; init; } = 0.01;

    /// <summary>Largest force the device renders.</summary>
    [Setting("Largest force the device renders (the Touch's nominal peak is 3.3 N; openhaptics also caps it at the device's nominal continuous force).", Units = "N", Minimum = 0, Maximum = 10)]
    public double MaxForceN { get; init; } = 3.3;

    /// <inheritdoc />
    public override IEnumerable<JsonProblem> CheckConsistency()
    {
        if (Backend == TouchBackendKind.Simulated && string.IsNullOrWhiteSpace(Script))
        {
            yield return new JsonProblem("script", "is required by the simulated back end");
        }
    }
}
