using NATS.Client.Core;

namespace RobotControl.Plugins.Link.Stations;

/// <summary>
/// The robot station's end of the link to the surgeon's station: its status out (<see cref="Publish"/> on
/// <see cref="StationAddress.StatusSubject"/>) and its commands in: a subscriber on <see cref="StationAddress.CommandSubject"/> that hands
/// each command to the station (an E-STOP goes to its safety supervisor, which never waits) and answers with what the
/// station said. A sender repeats a command until answered, so each command carries an id: a repeat gets the same
/// answer again and is acted on once. It runs on its own task and thread-pool threads, never on the loop or the bus thread, and the
/// robot station never needs it to stop safely (losing the link holds the arms through the master timeout).
/// </summary>
public sealed class RobotStationEndpoint : IAsyncDisposable
{
    private readonly NatsConnection _connection;
    private readonly Func<string, string> _act;
    private readonly CancellationTokenSource _stop = new();
    private readonly Dictionary<string, string> _answers = []; // by command id: a repeat gets the first answer again
    private readonly Task _serving;
    private StationStatus? _lastStatus;
    private long _lastPublished;

    private RobotStationEndpoint(StationAddress address, Func<string, string> act)
    {
        Address = address;
        _act = act;
        _connection = new NatsConnection(LinkEndpoint.Options(address.Url, $"robot station {address.Station}"));
        _serving = Task.Run(ServeAsync);
    }

    /// <summary>How often an unchanged status is published again (the surgeon's station's sign of life).</summary>
    public static readonly TimeSpan StatusEvery = TimeSpan.FromMilliseconds(200);

    /// <summary>Where it listens.</summary>
    public StationAddress Address { get; }

    /// <summary>Commands acted on (repeats not counted).</summary>
    public int Acted { get; private set; }

    /// <summary>The last connection error, or null.</summary>
    public string? LastError { get; private set; }

    /// <summary>
    /// Starts answering the commands on <paramref name="address"/>: <paramref name="act"/> gets each command's word
    /// (<see cref="StationCommands.EmergencyStop"/>) once and returns the answer's line.
    /// </summary>
    public static RobotStationEndpoint Start(StationAddress address, Func<string, string> act)
    {
        ArgumentNullException.ThrowIfNull(address);
        ArgumentNullException.ThrowIfNull(act);
        return new RobotStationEndpoint(address, act);
    }

    /// <summary>
    /// Publishes the station's status when it changed or <see cref="StatusEvery"/> has passed since the last; from any
    /// thread but the loop's and the bus's (a caller's progress poll). Never waits: a publish without a connection is
    /// dropped (the surgeon's station shows the link as lost after <see cref="SurgeonStationEndpoint.LostAfter"/>).
    /// </summary>
    public void Publish(StationStatus status)
    {
        ArgumentNullException.ThrowIfNull(status);
        var now = Environment.TickCount64;
        if (status == _lastStatus && now - _lastPublished < StatusEvery.TotalMilliseconds)
        {
            return;
        }

        _lastStatus = status;
        _lastPublished = now;
        if (_connection.ConnectionState == NatsConnectionState.Open)
        {
            _ = _connection.PublishAsync(Address.StatusSubject, status.ToJson()).AsTask().ContinueWith(t => LastError = t.Exception?.Message, TaskContinuationOptions.OnlyOnFaulted);
        }
    }

    /// <inheritdoc />
    public async ValueTask DisposeAsync()
    {
        await _stop.CancelAsync().ConfigureAwait(false);
        try
        {
            await _serving.ConfigureAwait(false);
        }
        catch (OperationCanceledException)
        {
            // stopped
        }

        await _connection.DisposeAsync().ConfigureAwait(false);
        _stop.Dispose();
    }

    private async Task ServeAsync()
    {
        while (!_stop.IsCancellationRequested)
        {
            try
            {
                await foreach (var message in _connection.SubscribeAsync<string>(Address.CommandSubject, cancellationToken: _stop.Token).ConfigureAwait(false))
                {
                    var answer = Answer(message.Data ?? string.Empty);
                    await message.ReplyAsync(answer, cancellationToken: _stop.Token).ConfigureAwait(false);
                }
            }
            catch (Exception ex) when (!_stop.IsCancellationRequested)
            {
                LastError = $"{Address.Url}: {LinkConnection.Describe(ex)}";
                await Task.Delay(TimeSpan.FromMilliseconds(200), _stop.Token).ConfigureAwait(false);
            }
        }
    }

    private string Answer(string request)
    {
        if (!StationCommands.TryParse(request, out var word, out var id))
        {
            return $"refused: '{request}' is not a command ({StationCommands.EmergencyStop} <id>)";
        }

        lock (_answers)
        {
            if (_answers.TryGetValue(id, out var given))
            {
                return given; // a repeat (its first answer came late or was lost): answered the same, not acted on again
            }

            Acted++;
            var answer = $"{word} {id}: {_act(word)}";
            _answers[id] = answer;
            return answer;
        }
    }
}
