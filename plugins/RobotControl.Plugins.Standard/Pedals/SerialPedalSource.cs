using RobotControl.Plugins.Sdk.Devices;
using RobotControl.Plugins.Sdk.Exchange;

namespace RobotControl.Plugins.Standard.Pedals;

/// <summary>
/// A pedal box on a device byte source (a serial, USB or TCP link the host opens): a reader thread parses frames and publishes the latest mask
/// through a <see cref="LatestValue{T}"/>, so the loop reads it without locks or waiting.
/// </summary>
public sealed class SerialPedalSource : IPedalSource
{
    private readonly Func<IByteSource> _open;
    private readonly LatestValue<int> _latest = new();
    private readonly PedalFrameParser _parser = new();
    private IByteSource? _link;
    private Thread? _reader;
    private volatile bool _stopping;

    /// <summary>Creates a source that opens its link with <paramref name="open"/> on <see cref="Start"/>.</summary>
    public SerialPedalSource(Func<IByteSource> open)
    {
        ArgumentNullException.ThrowIfNull(open);
        _open = open;
    }

    /// <summary>Frames received.</summary>
    public long Frames => _latest.PublishedCount;

    /// <summary>Frames rejected as corrupted.</summary>
    public long Rejected => _parser.Rejected;

    /// <inheritdoc />
    public void Start()
    {
        _link = _open();
        _stopping = false;
        _reader = new Thread(ReadLoop) { Name = "foot pedals", IsBackground = true };
        _reader.Start();
    }

    /// <inheritdoc />
    public int Read(double timeSeconds) => _latest.TryRead(out var mask) ? mask : 0;

    /// <inheritdoc />
    public void Dispose()
    {
        _stopping = true;
        _reader?.Join();
        _reader = null;
        _link?.Dispose();
        _link = null;
    }

    private void ReadLoop()
    {
        var buffer = new byte[64];
        while (!_stopping)
        {
            int n;
            try
            {
                n = _link!.Read(buffer, TimeSpan.FromMilliseconds(20));
            }
            catch (IOException)
            {
                // The box was unplugged: report nothing pressed (the safe state) and stop reading.
                _latest.Publish(0);
                return;
            }

            for (var i = 0; i < n; i++)
            {
                if (_parser.Feed(buffer[i], out var mask))
                {
                    _latest.Publish(mask);
                }
            }
        }
    }
}
