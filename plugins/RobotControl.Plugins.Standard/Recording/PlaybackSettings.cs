using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Standard.Recording;

/// <summary>Settings of <see cref="PlaybackPlugin"/>.</summary>
public sealed record PlaybackSettings : PluginSettings
{
    /// <summary>The recording (CSV with a <c>time_s</c> column).</summary>
    [Setting("Recording to play (CSV with a time_s column, as the recorder writes); every other column becomes an output of the same name.", IsFilePath = true, Required = true)]
    public string Path { get; init; } = "recording.csv";

    /// <summary>Interpolate linearly between rows (otherwise hold the last row).</summary>
    [Setting("Interpolate linearly between rows (off: hold each row until the next).")]
    public bool Interpolate { get; init; } = true;

    /// <summary>Start this far into the recording.</summary>
    [Setting("Start this far into the recording.", Units = "s", Minimum = 0, Maximum = 86400)]
    public double TimeOffsetS { get; init; }

    /// <summary>Repeat at the end.</summary>
    [Setting("Start again at the end (otherwise hold the last row).")]
    public bool Repeat { get; init; }
}
