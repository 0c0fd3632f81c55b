namespace RobotControl.Bus.Transports;

/// <summary>
/// A link its user keeps while the device behind it is closed for a moment and opened again
/// (<see cref="Released{T}"/>): e.g. to visit the bus at another baud, since one process owns a serial device at a
/// time and the device's settings (its baud) are shared by every descriptor open on it.
/// </summary>
public sealed class ReopenableLink : IByteLink
{
    private readonly Func<IByteLink> _open;
    private IByteLink? _inner;

    /// <summary>Opens the link with <paramref name="open"/>, which opens it again after each <see cref="Released{T}"/>.</summary>
    public ReopenableLink(Func<IByteLink> open)
    {
        ArgumentNullException.ThrowIfNull(open);
        _open = open;
        _inner = open();
        Description = _inner.Description;
        BaudRate = _inner.BaudRate;
    }

    /// <inheritdoc />
    public string Description { get; }

    /// <inheritdoc />
    public int BaudRate { get; }

    private IByteLink Inner => _inner ?? throw new ObjectDisposedException(Description, $"{Description} is closed");

    /// <summary>Closes the device, runs <paramref name="meanwhile"/> (which may open it itself), then opens it again, also when <paramref name="meanwhile"/> throws.</summary>
    public T Released<T>(Func<T> meanwhile)
    {
        ArgumentNullException.ThrowIfNull(meanwhile);
        Inner.Dispose();
        _inner = null;
        try
        {
            return meanwhile();
        }
        finally
        {
            _inner = _open();
        }
    }

    /// <inheritdoc />
    public void Write(ReadOnlySpan<byte> data) => Inner.Write(data);

    /// <inheritdoc />
    public int Read(Span<byte> buffer, TimeSpan timeout) => Inner.Read(buffer, timeout);

    /// <inheritdoc />
    public void DiscardInput() => Inner.DiscardInput();

    /// <inheritdoc />
    public void Dispose()
    {
        _inner?.Dispose();
        _inner = null;
    }
}
