using NATS.Client.Core;

namespace RobotControl.Plugins.Link;

/// <summary>
/// One end's connection to the NATS server, owned by that end's worker thread. The client connects in the background
/// and reconnects by itself with back-off (50 ms doubling to 1 s); a connection the client gives up on (the server
/// refused the credentials twice) is replaced after a second. <see cref="Connected"/> and <see cref="LastError"/> may
/// be read from any thread.
/// </summary>
internal sealed class LinkConnection : IAsyncDisposable
{
    private static readonly TimeSpan Retry = TimeSpan.FromSeconds(1);
    private static readonly TimeSpan PollPeriod = TimeSpan.FromMilliseconds(10);
    private readonly NatsOpts _options;
    private readonly string _credentials;
    private volatile NatsConnection _connection; // replaced by the worker, read by the loop (Connected)
    private Task? _connecting;
    private long _connectingSince;
    private volatile string? _lastError;

    public LinkConnection(LinkSettings settings, string instanceName)
    {
        _options = LinkEndpoint.Options(settings, instanceName);
        _credentials = settings.User.Length > 0 ? $"user '{settings.User}' and a password" : settings.Token.Length > 0 ? "a token" : "none";
        _connection = Create();
    }

    /// <summary>The client (replaced when it gave up).</summary>
    public NatsConnection Client => _connection;

    /// <summary>True while the connection to the server is open.</summary>
    public bool Connected => _connection.ConnectionState == NatsConnectionState.Open;

    /// <summary>The last connection or publishing error, naming the server; null before any.</summary>
    public string? LastError
    {
        get => _lastError;
        set => _lastError = value;
    }

    /// <summary>
    /// Starts connecting, or waits up to 10 ms for the connection (or the client's own reconnection) to open; true
    /// when it is open. A client that failed or gave up (state closed) is replaced after a second.
    /// </summary>
    public async Task<bool> EnsureConnectedAsync(CancellationToken stop)
    {
        if (Connected)
        {
            return true;
        }

        if (_connecting is null)
        {
            _connecting = _connection.ConnectAsync().AsTask();
            _connectingSince = Environment.TickCount64;
        }
        else if (!_connecting.IsCompleted && Environment.TickCount64 - _connectingSince > _options.ConnectTimeout.TotalMilliseconds)
        {
            LastError = $"{_options.Url}: no server answers (still trying)";
        }

        if (_connecting.IsFaulted || (_connecting.IsCompleted && _connection.ConnectionState == NatsConnectionState.Closed))
        {
            LastError = $"{_options.Url}: {(_connecting.Exception is { } failure ? Describe(failure) : "the client gave up reconnecting")} (credentials: {_credentials})";
            await _connection.DisposeAsync().ConfigureAwait(false);
            _connection = Create();
            _connecting = null;
            await Task.Delay(Retry, stop).ConfigureAwait(false);
            return false;
        }

        // Connected once and now reconnecting by itself: poll (the finished connect task would return at once: a busy loop).
        var poll = Task.Delay(PollPeriod, stop);
        await (_connecting.IsCompleted ? poll : Task.WhenAny(_connecting, poll)).ConfigureAwait(false);
        return Connected;
    }

    public ValueTask DisposeAsync() => _connection.DisposeAsync();

    /// <summary>The messages of an exception and its inner ones, outermost first, without repeats.</summary>
    public static string Describe(Exception exception)
    {
        var messages = new List<string>();
        for (var e = exception; e is not null; e = e.InnerException)
        {
            if (e is not AggregateException && !messages.Contains(e.Message))
            {
                messages.Add(e.Message);
            }
        }

        return string.Join(": ", messages);
    }

    private NatsConnection Create()
    {
        var connection = new NatsConnection(_options);
        connection.ConnectionDisconnected += (_, _) =>
        {
            LastError = $"{_options.Url}: connection lost";
            return ValueTask.CompletedTask;
        };
        connection.ReconnectFailed += (_, args) =>
        {
            LastError = $"{_options.Url}: reconnection failed: {args.Message}";
            return ValueTask.CompletedTask;
        };
        return connection;
    }
}
