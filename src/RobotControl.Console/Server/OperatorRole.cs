namespace RobotControl.WebConsole.Server;

/// <summary>
/// The operator role: actions that move the robot or write parameters need it, and one console holds it at a time
/// (the others watch). Consoles name themselves with the <see cref="ClientHeader"/> header. The holder keeps it while
/// it keeps talking to the server; after <see cref="Lease"/> of silence another console may take it. Thread-safe.
/// </summary>
public sealed class OperatorRole(TimeProvider time)
{
    /// <summary>The request header that names a console.</summary>
    public const string ClientHeader = "X-Console-Client";

    /// <summary>How long the role outlives its holder's last request.</summary>
    public static readonly TimeSpan Lease = TimeSpan.FromSeconds(10);

    private readonly Lock _lock = new();
    private string? _holder;
    private long _lastSeen;

    /// <summary>The console holding the role, or null.</summary>
    public string? Holder
    {
        get
        {
            lock (_lock)
            {
                return Expired() ? null : _holder;
            }
        }
    }

    /// <summary>Takes the role for <paramref name="client"/> if it is free (or already its own). Returns true when held.</summary>
    public bool TryClaim(string client)
    {
        lock (_lock)
        {
            if (_holder is null || _holder == client || Expired())
            {
                _holder = client;
                _lastSeen = time.GetTimestamp();
                return true;
            }

            return false;
        }
    }

    /// <summary>Gives the role up if <paramref name="client"/> holds it.</summary>
    public void Release(string client)
    {
        lock (_lock)
        {
            if (_holder == client)
            {
                _holder = null;
            }
        }
    }

    /// <summary>True when <paramref name="client"/> holds the role (and renews its lease).</summary>
    public bool IsHeldBy(string? client)
    {
        lock (_lock)
        {
            if (client is null || _holder != client || Expired())
            {
                return false;
            }

            _lastSeen = time.GetTimestamp();
            return true;
        }
    }

    private bool Expired() => _holder is not null && time.GetElapsedTime(_lastSeen) > Lease;
}
