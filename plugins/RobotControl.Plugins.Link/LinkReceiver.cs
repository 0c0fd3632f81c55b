using NATS.Client.Core;
using RobotControl.Plugins.Sdk.Exchange;

namespace RobotControl.Plugins.Link;

/// <summary>
/// link_in's subscriber thread: decodes every frame on the subject, counts what is wrong with the stream (bad frames,
/// gaps in the sequence, reordered or duplicate samples) and publishes the newest sample for the loop. A bad frame
/// is counted and described (<see cref="LastBadFrame"/>), never thrown; an old or repeated sample never replaces a
/// newer one. The loop never waits on any of it.
/// </summary>
internal sealed class LinkReceiver : IDisposable
{
    private readonly LinkInSettings _settings;
    private readonly string _instanceName;
    private readonly TimeProvider _time;
    private readonly LatestValue<LinkSample> _latest;
    private readonly uint _layout;
    private readonly int _count;
    private readonly CancellationTokenSource _stop = new();
    private LinkConnection? _connection;
    private LinkSample _sample;
    private Thread? _thread;
    private long _received;
    private long _gaps;
    private long _reordered;
    private long _badFrames;
    private long _senders;
    private volatile string? _lastBadFrame;
    private int _disposed;

    public LinkReceiver(LinkInSettings settings, string instanceName, IReadOnlyList<string> signals, TimeProvider time, LatestValue<LinkSample> latest)
    {
        _settings = settings;
        _instanceName = instanceName;
        _time = time;
        _latest = latest;
        _layout = LinkFrame.Layout(signals);
        _count = signals.Count;
    }

    /// <summary>True while the connection to the server is open.</summary>
    public bool Connected => _connection?.Connected ?? false;

    /// <summary>Frames received (good and bad).</summary>
    public long Received => Interlocked.Read(ref _received);

    /// <summary>Sequence numbers skipped (samples lost on the way or dropped by the sender).</summary>
    public long Gaps => Interlocked.Read(ref _gaps);

    /// <summary>Samples that came after a newer one, or twice (not shown).</summary>
    public long Reordered => Interlocked.Read(ref _reordered);

    /// <summary>Frames that could not be decoded.</summary>
    public long BadFrames => Interlocked.Read(ref _badFrames);

    /// <summary>Sender runs seen (a restarted link_out starts a new run and its sequence again).</summary>
    public long Senders => Interlocked.Read(ref _senders);

    /// <summary>What was wrong with the last bad frame (instance, subject, reason); null before any.</summary>
    public string? LastBadFrame => _lastBadFrame;

    /// <summary>The last connection error; null before any.</summary>
    public string? LastError => _connection?.LastError;

    public void Start()
    {
        _connection = new LinkConnection(_settings, _instanceName);
        _thread = new Thread(() => RunAsync(_connection).GetAwaiter().GetResult()) { IsBackground = true, Name = $"link_in {_instanceName}" };
        _thread.Start();
    }

    public void Dispose()
    {
        if (Interlocked.Exchange(ref _disposed, 1) != 0)
        {
            return;
        }

        _stop.Cancel();
        _thread?.Join(TimeSpan.FromSeconds(5));
        _stop.Dispose();
    }

    /// <summary>Takes one frame as it came off the wire (subscriber thread; the tests feed it directly too).</summary>
    internal void Accept(ReadOnlySpan<byte> frame)
    {
        var problem = Take(frame);
        Interlocked.Increment(ref _received); // after the sample is published: a reader that sees the count sees the sample
        if (problem is not null)
        {
            Interlocked.Increment(ref _badFrames);
            _lastBadFrame = $"'{_instanceName}': bad frame on {_settings.Subject}: {problem}"; // last: all counts are in
        }
    }

    // Decodes and checks the order of one frame, publishing it when it is the newest; returns what is wrong with it, or null.
    private string? Take(ReadOnlySpan<byte> frame)
    {
        var arrivalNs = LinkFrame.UnixNs(_time.GetUtcNow());
        var previous = _sample;
        var problem = LinkFrame.Read(frame, _layout, _count, ref _sample);
        if (problem is not null)
        {
            return problem;
        }

        if (_sample.Sender != previous.Sender || previous.Sequence == 0)
        {
            Interlocked.Increment(ref _senders);
        }
        else if (_sample.Sequence <= previous.Sequence)
        {
            Interlocked.Increment(ref _reordered);
            _sample = previous;
            return null;
        }
        else if (_sample.Sequence > previous.Sequence + 1)
        {
            Interlocked.Add(ref _gaps, _sample.Sequence - previous.Sequence - 1);
        }

        _sample.TransitMs = Math.Max(0, arrivalNs - _sample.WallNs) / 1e6;
        _latest.Publish(in _sample);
        return null;
    }

    private async Task RunAsync(LinkConnection connection)
    {
        var stop = _stop.Token;
        try
        {
            while (!stop.IsCancellationRequested)
            {
                await SubscribeAsync(connection, stop).ConfigureAwait(false);
            }
        }
        catch (OperationCanceledException) when (stop.IsCancellationRequested)
        {
        }
        finally
        {
            await connection.DisposeAsync().ConfigureAwait(false);
        }
    }

    private async Task SubscribeAsync(LinkConnection connection, CancellationToken stop)
    {
        try
        {
            if (!await connection.EnsureConnectedAsync(stop).ConfigureAwait(false))
            {
                return;
            }

            // The subscription outlives reconnections (the client subscribes again); it ends when the client is closed.
            await foreach (var message in connection.Client.SubscribeAsync<byte[]>(_settings.Subject, cancellationToken: stop).ConfigureAwait(false))
            {
                Accept(message.Data ?? []);
            }
        }
        catch (NatsException ex)
        {
            connection.LastError = $"{_settings.Url}: subscribing to {_settings.Subject}: {ex.Message}";
        }

        await Task.Delay(TimeSpan.FromMilliseconds(100), stop).ConfigureAwait(false);
    }
}
