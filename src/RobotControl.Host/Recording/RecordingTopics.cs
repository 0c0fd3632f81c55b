namespace RobotControl.Host.Recording;

/// <summary>The topics of a session recording that readers look up by name (docs/recording.md lists them all).</summary>
public static class RecordingTopics
{
    /// <summary>Every output signal of the graph.</summary>
    public const string Signals = "/graph/signals";

    /// <summary>Tool poses (<c>foxglove.FrameTransforms</c>).</summary>
    public const string Transforms = "/tf";

    /// <summary>Run-level transitions.</summary>
    public const string RunLevel = "/safety/run_level";

    /// <summary>Safety trips.</summary>
    public const string Trips = "/safety/trips";

    /// <summary>Operator commands.</summary>
    public const string Operator = "/operator/commands";

    /// <summary>Bus statistics.</summary>
    public const string Bus = "/bus/statistics";

    /// <summary>Module status.</summary>
    public const string Modules = "/modules/status";

    /// <summary>One arm's joints.</summary>
    public static string Joints(string arm) => $"/arms/{arm}/joints";
}
