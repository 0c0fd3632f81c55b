using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Touch.OpenHaptics;
using RobotControl.Plugins.Touch.Simulation;

namespace RobotControl.Plugins.Touch.Backends;

/// <summary>Creates the back end a Touch instance's (already validated) settings name.</summary>
internal static class TouchBackends
{
    public static ITouchBackend Create(TouchSettings settings, PluginContext context) => settings.Backend switch
    {
        TouchBackendKind.Simulated => SimulatedTouchBackend.Create(settings, context),
        TouchBackendKind.Openhaptics => new OpenHapticsTouchBackend(OpenHapticsOptions.From(settings, context)),
        _ => throw new ArgumentOutOfRangeException(nameof(settings), settings.Backend, "unknown Touch back end"),
    };
}
