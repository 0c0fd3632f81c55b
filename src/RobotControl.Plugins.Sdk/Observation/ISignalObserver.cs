namespace RobotControl.Plugins.Sdk.Observation;

/// <summary>
/// Implemented by plug-ins that watch every signal of the graph (a recorder, a display). The host attaches the graph's
/// view once before <see cref="Plugin.Start"/> and ticks observers after every other instance, so they see each
/// tick's final values. An observer's own outputs cannot feed other instances.
/// </summary>
public interface ISignalObserver
{
    /// <summary>Receives the view of every output signal of the graph.</summary>
    void Attach(SignalView view);
}
