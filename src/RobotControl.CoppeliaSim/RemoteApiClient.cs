using NetMQ;
using NetMQ.Sockets;
using RobotControl.CoppeliaSim.Protocol;

namespace RobotControl.CoppeliaSim;

/// <summary>
/// A client of CoppeliaSim's ZeroMQ remote API: a REQ socket to the server's REP socket, CBOR messages. Every call
/// has a deadline; a call that misses it (or a server that sends <c>_*end*_</c>) leaves the REQ socket waiting for a
/// reply that will never come, so the socket is thrown away and a new one connected before the next call. Handles
/// <c>_*wait*_</c> (answers <c>_*executed*_</c> until the result comes), <c>_*repeat*_</c> (sends the last request
/// again) and callbacks (runs the registered handler, answers <c>_*executed*_</c> with its results). Not
/// thread-safe: one thread owns a client.
/// </summary>
public sealed class RemoteApiClient : IDisposable
{
    private readonly Dictionary<string, Func<IReadOnlyList<object?>, IReadOnlyList<object?>>> _callbacks = new(StringComparer.Ordinal);
    private RequestSocket? _socket;
    private bool _contacted;

    /// <summary>Creates a client of the server at <paramref name="endpoint"/> (e.g. <c>tcp://127.0.0.1:23000</c>); connects lazily.</summary>
    /// <param name="endpoint">ZeroMQ endpoint.</param>
    /// <param name="callTimeout">Deadline of every call (wait replies included).</param>
    public RemoteApiClient(string endpoint, TimeSpan callTimeout)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(endpoint);
        ArgumentOutOfRangeException.ThrowIfLessThanOrEqual(callTimeout, TimeSpan.Zero);
        Endpoint = endpoint;
        CallTimeout = callTimeout;
        Uuid = Guid.NewGuid().ToString();
    }

    /// <summary>The server's endpoint.</summary>
    public string Endpoint { get; }

    /// <summary>Deadline of every call.</summary>
    public TimeSpan CallTimeout { get; }

    /// <summary>This client's identifier (sent with every request).</summary>
    public string Uuid { get; }

    /// <summary>Round trips completed (each request/reply pair, wait and repeat answers included).</summary>
    public long RoundTrips { get; private set; }

    /// <summary>Times the socket was (re)created.</summary>
    public int Connections { get; private set; }

    /// <summary>Registers the handler of a callback the server may ask this client to run during a call.</summary>
    public void RegisterCallback(string name, Func<IReadOnlyList<object?>, IReadOnlyList<object?>> handler)
    {
        ArgumentException.ThrowIfNullOrEmpty(name);
        ArgumentNullException.ThrowIfNull(handler);
        _callbacks[name] = handler;
    }

    /// <summary>Calls <paramref name="func"/> with <paramref name="args"/> and returns its results.</summary>
    /// <exception cref="CoppeliaSimServerException">The server reported an error (its message, newlines and tabs restored).</exception>
    /// <exception cref="CoppeliaSimConnectionException">No reply before the deadline, or the server ended the session; the socket is recreated on the next call.</exception>
    public IReadOnlyList<object?> Call(string func, params object?[] args)
    {
        ArgumentException.ThrowIfNullOrEmpty(func);
        ArgumentNullException.ThrowIfNull(args);
        var deadline = Environment.TickCount64 + (long)CallTimeout.TotalMilliseconds;
        var request = func;
        IReadOnlyList<object?> requestArgs = args;
        while (true)
        {
            var reply = RoundTrip(request, requestArgs, deadline, func);
            switch (reply.Func)
            {
                case null when reply.Error is not null:
                    throw new CoppeliaSimServerException($"{func}: {reply.Error}");
                case null:
                    return reply.Ret;
                case RemoteApiWords.Wait:
                    (request, requestArgs) = (RemoteApiWords.Executed, []);
                    break;
                case RemoteApiWords.Repeat:
                    break;
                case RemoteApiWords.End:
                    Disconnect();
                    throw new CoppeliaSimConnectionException($"{func}: the server ended the session ({Endpoint})");
                default:
                    requestArgs = _callbacks.TryGetValue(reply.Func, out var handler) ? handler(reply.Args) : [];
                    request = RemoteApiWords.Executed;
                    break;
            }
        }
    }

    /// <summary>Drops the socket; the next call connects a new one.</summary>
    public void Disconnect()
    {
        _socket?.Dispose();
        _socket = null;
    }

    /// <inheritdoc />
    public void Dispose() => Disconnect();

    private RemoteApiReply RoundTrip(string func, IReadOnlyList<object?> args, long deadline, string call)
    {
        var socket = Socket();
        var bytes = RemoteApiCodec.Encode(new RemoteApiRequest(func, args, Uuid, _contacted ? null : (int)Math.Ceiling(CallTimeout.TotalSeconds)));
        if (!socket.TrySendFrame(Remaining(deadline), bytes))
        {
            Disconnect();
            throw new CoppeliaSimConnectionException($"{call}: could not send to {Endpoint} within {CallTimeout.TotalMilliseconds:0} ms");
        }

        if (!socket.TryReceiveFrameBytes(Remaining(deadline), out var replyBytes))
        {
            Disconnect();
            throw new CoppeliaSimConnectionException($"{call}: no reply from {Endpoint} within {CallTimeout.TotalMilliseconds:0} ms");
        }

        _contacted = true;
        RoundTrips++;
        try
        {
            return RemoteApiCodec.DecodeReply(replyBytes);
        }
        catch (FormatException ex)
        {
            Disconnect();
            throw new CoppeliaSimConnectionException($"{call}: unreadable reply from {Endpoint}: {ex.Message}", ex);
        }
    }

    private static TimeSpan Remaining(long deadline) => TimeSpan.FromMilliseconds(Math.Max(0, deadline - Environment.TickCount64));

    private RequestSocket Socket()
    {
        if (_socket is not null)
        {
            return _socket;
        }

        var socket = new RequestSocket();
        socket.Options.Linger = TimeSpan.Zero;
        socket.Connect(Endpoint);
        _socket = socket;
        _contacted = false;
        Connections++;
        return socket;
    }
}
