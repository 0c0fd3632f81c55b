using RobotControl.Plugins.Sdk;

namespace RobotControl.Plugins.Touch.OpenHaptics;

/// <summary>What the OpenHaptics back end needs from a Touch instance's settings.</summary>
/// <param name="Instance">The instance name (for messages).</param>
/// <param name="DeviceName">The configured device name; empty for HD_DEFAULT_DEVICE.</param>
/// <param name="LibraryPath">The HD library or its folder, resolved against the graph file; empty to search.</param>
/// <param name="MaxForceN">The configured force limit (further capped at the device's continuous maximum).</param>
/// <param name="RampFrames">Servo frames over which force is ramped in.</param>
/// <param name="StaleFrames">Servo frames after which an unrenewed force is stale.</param>
internal sealed record OpenHapticsOptions(string Instance, string DeviceName, string LibraryPath, double MaxForceN, int RampFrames, int StaleFrames)
{
    /// <summary>The device as named in messages.</summary>
    public string DeviceLabel => DeviceName.Length == 0 ? "default device" : $"device '{DeviceName}'";

    /// <summary>The options of validated settings.</summary>
    public static OpenHapticsOptions From(TouchSettings settings, PluginContext context)
    {
        var library = settings.LibraryPath.Length == 0 ? "" : context.ResolvePath(settings.LibraryPath);
        return new OpenHapticsOptions(
            context.InstanceName,
            settings.Device.Trim(),
            library,
            settings.MaxForceN,
            (int)Math.Round(settings.ForceRampS * HdConstants.ServoRateHz),
            Math.Max(1, (int)Math.Ceiling(settings.StaleAfterMs * HdConstants.ServoRateHz / 1000.0)));
    }
}
