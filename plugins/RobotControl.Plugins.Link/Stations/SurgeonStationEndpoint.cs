using System.Diagnostics;
using System.Globalization;
using NATS.Client.Core;

namespace RobotControl.Plugins.Link.Stations;

/// <summary>
/// The surgeon station's end of the link to a robot station: its commands out (<see cref="SendAsync"/> repeats one
/// every <see cref="Repeat"/> until it is answered or <see cref="GiveUpAfter"/> has passed) and the robot station's
/// status in (<see cref="Watch"/>: each change, and the link lost after <see cref="LostAfter"/> without a status). The
/// connection is opened when built and kept, so an E-STOP does not wait for a connect.
/// </summary>
public sealed class SurgeonStationEndpoint : IAsyncDisposable
{
    /// <summary>How long one attempt waits for the answer before the command is sent again.</summary>
    public static readonly TimeSpan Repeat = TimeSpan.FromMilliseconds(100);

    /// <summary>How long a command is repeated before the sender says it was not answered.</summary>
    public static readonly TimeSpan GiveUpAfter = TimeSpan.FromSeconds(5);

    /// <summary>How long without a status from the robot station before the link is shown as lost.</summary>
    public static readonly TimeSpan LostAfter = TimeSpan.FromSeconds(1);

    private readonly NatsConnection _connection;
    private readonly CancellationTokenSource _stop = new();
    private Task? _watching;

    private SurgeonStationEndpoint(StationAddress address)
    {
        Address = address;
        _connection = new NatsConnection(LinkEndpoint.Options(address.Url, $"surgeon station for {address.Station}"));
        _ = _connection.ConnectAsync().AsTask().ContinueWith(static t => _ = t.Exception, TaskScheduler.Default); // in the background; reconnects by itself
    }

    /// <summary>Where the commands go.</summary>
    public StationAddress Address { get; }

    /// <summary>A sender to <paramref name="address"/>.</summary>
    public static SurgeonStationEndpoint Open(StationAddress address)
    {
        ArgumentNullException.ThrowIfNull(address);
        return new SurgeonStationEndpoint(address);
    }

    /// <summary>Sends <paramref name="word"/> until the robot station answers; the answer, or why there is none.</summary>
    public async Task<StationCommandOutcome> SendAsync(string word, CancellationToken cancel = default)
    {
        var request = StationCommands.New(word);
        var started = Stopwatch.GetTimestamp();
        var attempts = 0;
        string? last = null;
        while (Stopwatch.GetElapsedTime(started) < GiveUpAfter && !cancel.IsCancellationRequested)
        {
            attempts++;
            try
            {
                var reply = await _connection.RequestAsync<string, string>(Address.CommandSubject, request, replyOpts: new NatsSubOpts { Timeout = Repeat }, cancellationToken: cancel).ConfigureAwait(false);
                return new StationCommandOutcome(true, reply.Data ?? string.Empty, Stopwatch.GetElapsedTime(started), attempts);
            }
            catch (Exception ex) when (!cancel.IsCancellationRequested)
            {
                // Whatever went wrong (no connection yet: the client cancels the publish; nobody subscribed; no answer in
                // time), the command is sent again until GiveUpAfter: an E-STOP is never dropped on an exception.
                last = ex is OperationCanceledException ? "not connected to the server yet" : LinkConnection.Describe(ex);
                if (ex is not NatsNoReplyException)
                {
                    await Task.Delay(Repeat, cancel).ConfigureAwait(false); // answered at once (no connection, no responder): wait before the next
                }
            }
        }

        return new StationCommandOutcome(false, $"no answer from robot station '{Address.Station}' on {Address.Url} within {GiveUpAfter.TotalSeconds:0} s ({attempts} attempts; last: {last ?? "none"})", Stopwatch.GetElapsedTime(started), attempts);
    }

    /// <summary>
    /// Watches the robot station's status: <paramref name="tell"/> gets a line for each change of run level or trips,
    /// when no status has come for <see cref="LostAfter"/> (the link or the robot station is gone: its arms hold on
    /// their own), and when they come again. Called on a thread-pool thread, never the loop's.
    /// </summary>
    public void Watch(Action<string> tell)
    {
        ArgumentNullException.ThrowIfNull(tell);
        _watching = Task.Run(() => WatchAsync(tell));
    }

    /// <inheritdoc />
    public async ValueTask DisposeAsync()
    {
        await _stop.CancelAsync().ConfigureAwait(false);
        if (_watching is { } watching)
        {
            await watching.ContinueWith(static _ => { }, TaskScheduler.Default).ConfigureAwait(false);
        }

        await _connection.DisposeAsync().ConfigureAwait(false);
        _stop.Dispose();
    }

    private async Task WatchAsync(Action<string> tell)
    {
        StationStatus? shown = null;
        var heard = Stopwatch.GetTimestamp();
        var lost = true; // until the first status: said once it has been LostAfter
        var saidNever = false;
        var statuses = System.Threading.Channels.Channel.CreateBounded<StationStatus>(new System.Threading.Channels.BoundedChannelOptions(16) { FullMode = System.Threading.Channels.BoundedChannelFullMode.DropOldest });
        _ = Task.Run(async () =>
        {
            while (!_stop.IsCancellationRequested)
            {
                try
                {
                    await foreach (var message in _connection.SubscribeAsync<string>(Address.StatusSubject, cancellationToken: _stop.Token).ConfigureAwait(false))
                    {
                        if (StationStatus.Parse(message.Data) is { } status)
                        {
                            statuses.Writer.TryWrite(status);
                        }
                    }
                }
                catch (Exception) when (!_stop.IsCancellationRequested)
                {
                    await Task.Delay(Repeat, _stop.Token).ConfigureAwait(false); // no connection yet, or lost: subscribe again
                }
            }
        });
        while (!_stop.IsCancellationRequested)
        {
            using var wait = CancellationTokenSource.CreateLinkedTokenSource(_stop.Token);
            wait.CancelAfter(Repeat);
            try
            {
                var status = await statuses.Reader.ReadAsync(wait.Token).ConfigureAwait(false);
                heard = Stopwatch.GetTimestamp();
                if (lost && (shown is not null || saidNever))
                {
                    tell($"link to robot station '{Address.Station}' is back");
                }

                lost = false;
                if (status != shown)
                {
                    shown = status;
                    tell(status.Line(Address.Station));
                }
            }
            catch (OperationCanceledException) when (!_stop.IsCancellationRequested)
            {
                if (!lost && Stopwatch.GetElapsedTime(heard) > LostAfter)
                {
                    lost = true;
                    tell(string.Create(CultureInfo.InvariantCulture, $"LINK LOST: no status from robot station '{Address.Station}' for {Stopwatch.GetElapsedTime(heard).TotalSeconds:0.0} s on {Address.Url}: its arms hold on their own (master timeout); this station's E-STOP cannot reach it, use the robot's E-STOP"));
                }
                else if (lost && shown is null && !saidNever && Stopwatch.GetElapsedTime(heard) > LostAfter)
                {
                    saidNever = true;
                    tell(string.Create(CultureInfo.InvariantCulture, $"no status from robot station '{Address.Station}' on {Address.Url} yet ({LostAfter.TotalSeconds:0.#} s)"));
                }
            }
        }
    }
}

/// <summary>What became of a command.</summary>
/// <param name="Answered">True when the robot station answered.</param>
/// <param name="Line">Its answer, or why there is none.</param>
/// <param name="After">From the first send to the answer (or giving up).</param>
/// <param name="Attempts">Times the command was sent.</param>
public sealed record StationCommandOutcome(bool Answered, string Line, TimeSpan After, int Attempts);
