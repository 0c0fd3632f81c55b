using System.Diagnostics;
using NATS.Client.Core;

namespace RobotControl.Plugins.Link.Stations;

/// <summary>
/// The surgeon station's end of the commands: sends one to the robot station and repeats it every
/// <see cref="Repeat"/> until it is answered or <see cref="GiveUpAfter"/> has passed. The connection is opened when
/// built and kept, so an E-STOP does not wait for a connect.
/// </summary>
public sealed class StationCommandSender : IAsyncDisposable
{
    /// <summary>How long one attempt waits for the answer before the command is sent again.</summary>
    public static readonly TimeSpan Repeat = TimeSpan.FromMilliseconds(100);

    /// <summary>How long a command is repeated before the sender says it was not answered.</summary>
    public static readonly TimeSpan GiveUpAfter = TimeSpan.FromSeconds(5);

    private readonly NatsConnection _connection;

    private StationCommandSender(StationAddress address)
    {
        Address = address;
        _connection = new NatsConnection(LinkEndpoint.Options(address.Url, $"surgeon station for {address.Station}"));
        _ = _connection.ConnectAsync().AsTask().ContinueWith(static t => _ = t.Exception, TaskScheduler.Default); // in the background; reconnects by itself
    }

    /// <summary>Where the commands go.</summary>
    public StationAddress Address { get; }

    /// <summary>A sender to <paramref name="address"/>.</summary>
    public static StationCommandSender Open(StationAddress address)
    {
        ArgumentNullException.ThrowIfNull(address);
        return new StationCommandSender(address);
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

    /// <inheritdoc />
    public ValueTask DisposeAsync() => _connection.DisposeAsync();
}

/// <summary>What became of a command.</summary>
/// <param name="Answered">True when the robot station answered.</param>
/// <param name="Line">Its answer, or why there is none.</param>
/// <param name="After">From the first send to the answer (or giving up).</param>
/// <param name="Attempts">Times the command was sent.</param>
public sealed record StationCommandOutcome(bool Answered, string Line, TimeSpan After, int Attempts);
