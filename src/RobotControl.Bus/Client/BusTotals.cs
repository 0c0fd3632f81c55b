namespace RobotControl.Bus.Client;

/// <summary>Traffic counters summed over a set of modules (<see cref="BusClient.Totals"/>).</summary>
/// <param name="Frames">Frames sent to and received from them.</param>
/// <param name="CrcErrors">Replies that arrived with a bad CRC.</param>
/// <param name="Timeouts">Replies that did not arrive in time.</param>
/// <param name="Retries">Requests sent again.</param>
public readonly record struct BusTotals(long Frames, long CrcErrors, long Timeouts, long Retries);
