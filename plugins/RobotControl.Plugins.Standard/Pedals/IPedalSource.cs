namespace RobotControl.Plugins.Standard.Pedals;

/// <summary>Where pedal states come from: a serial pedal box (reader thread) or a script (loop time).</summary>
public interface IPedalSource : IDisposable
{
    /// <summary>Starts reading (opens the device, starts its thread).</summary>
    void Start();

    /// <summary>The latest pedal mask (bit i = pedal i+1 pressed) at loop time <paramref name="timeSeconds"/>. Non-blocking, allocation-free.</summary>
    int Read(double timeSeconds);
}
