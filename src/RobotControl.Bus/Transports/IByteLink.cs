namespace RobotControl.Bus.Transports;

/// <summary>
/// A half-duplex byte link to the module bus (serial port, USB adapter, TCP bridge or the in-process virtual bus).
/// One thread uses a link at a time.
/// </summary>
public interface IByteLink : IDisposable
{
    /// <summary>What the link is connected to, for messages.</summary>
    string Description { get; }

    /// <summary>Bits per second on the bus (used for wire-time budgets and timeouts).</summary>
    int BaudRate { get; }

    /// <summary>Sends bytes (returns once they are queued to the wire).</summary>
    void Write(ReadOnlySpan<byte> data);

    /// <summary>
    /// Receives whatever bytes arrive, waiting at most <paramref name="timeout"/> for the first one. Returns the number
    /// of bytes read; 0 when nothing arrived in time.
    /// </summary>
    int Read(Span<byte> buffer, TimeSpan timeout);

    /// <summary>Drops bytes received but not yet read.</summary>
    void DiscardInput();
}
