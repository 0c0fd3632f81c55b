namespace RobotControl.Plugins.Link;

/// <summary>
/// link_out's sender thread: takes the frames the loop queued, oldest first, and publishes them. While the server is
/// unreachable the queued frames are discarded and counted (a sample sent after the reconnection would arrive old),
/// so after a reconnection the first sample published is a fresh one. The loop never waits on any of it.
/// </summary>
internal sealed class LinkSender : IDisposable
{
    private readonly LinkOutSettings _settings;
    private readonly string _instanceName;
    private readonly FrameRing _ring;
    private readonly AutoResetEvent _wake = new(false);
    private readonly CancellationTokenSource _stop = new();
    private LinkConnection? _connection;
    private Thread? _thread;
    private long _sent;
    private long _unsent;
    private int _disposed;

    public LinkSender(LinkOutSettings settings, string instanceName, FrameRing ring)
    {
        _settings = settings;
        _instanceName = instanceName;
        _ring = ring;
    }

    /// <summary>True while the connection to the server is open.</summary>
    public bool Connected => _connection?.Connected ?? false;

    /// <summary>Frames published.</summary>
    public long Sent => Interlocked.Read(ref _sent);

    /// <summary>Frames discarded while disconnected or whose publishing failed.</summary>
    public long Unsent => Interlocked.Read(ref _unsent);

    /// <summary>The last connection or publishing error; null before any.</summary>
    public string? LastError => _connection?.LastError;

    public void Start()
    {
        _connection = new LinkConnection(_settings, _instanceName);
        _thread = new Thread(() => Run(_connection)) { IsBackground = true, Name = $"link_out {_instanceName}" };
        _thread.Start();
    }

    /// <summary>Tells the thread a frame is queued (loop; never blocks).</summary>
    public void Wake() => _wake.Set();

    public void Dispose()
    {
        if (Interlocked.Exchange(ref _disposed, 1) != 0)
        {
            return;
        }

        _stop.Cancel();
        _wake.Set();
        _thread?.Join(TimeSpan.FromSeconds(5));
        _stop.Dispose();
        _wake.Dispose();
    }

    // Synchronous on the sender's own thread: it alone waits (for the loop's wake-up, for a publish to complete), never
    // a thread-pool thread, which the client's own reading and writing need (a starved pool would delay both).
    private void Run(LinkConnection connection)
    {
        var frame = new byte[_ring.FrameLength];
        var stop = _stop.Token;
        try
        {
            while (!stop.IsCancellationRequested)
            {
                if (!connection.Connected && !connection.EnsureConnectedAsync(stop).GetAwaiter().GetResult())
                {
                    Discard(frame);
                    continue;
                }

                _wake.WaitOne(TimeSpan.FromMilliseconds(100));
                while (!stop.IsCancellationRequested && _ring.TryRead(frame))
                {
                    Publish(connection, frame, stop);
                }
            }
        }
        catch (OperationCanceledException) when (stop.IsCancellationRequested)
        {
        }
        finally
        {
            connection.DisposeAsync().AsTask().GetAwaiter().GetResult();
        }
    }

    private void Publish(LinkConnection connection, byte[] frame, CancellationToken stop)
    {
        if (!connection.Connected)
        {
            Interlocked.Increment(ref _unsent);
            return;
        }

        try
        {
            var pending = connection.Client.PublishAsync(_settings.Subject, frame, cancellationToken: stop);
            if (!pending.IsCompletedSuccessfully)
            {
                pending.AsTask().GetAwaiter().GetResult();
            }

            Interlocked.Increment(ref _sent);
        }
        catch (NATS.Client.Core.NatsException ex)
        {
            Interlocked.Increment(ref _unsent);
            connection.LastError = $"{_settings.Url}: publishing on {_settings.Subject}: {ex.Message}";
        }
    }

    private void Discard(byte[] frame)
    {
        while (_ring.TryRead(frame))
        {
            Interlocked.Increment(ref _unsent);
        }
    }
}
