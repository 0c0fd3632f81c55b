namespace RobotControl.Bus.Client;

/// <summary>
/// A way to cut a long piece of bus work short: while a <see cref="BusClient"/> has one (<see cref="BusClient.Interruption"/>)
/// and it is raised, the client's next frame is not sent and <see cref="BusWorkInterruptedException"/> is thrown instead.
/// The owner of the bus sets it around work that may be cut short (discovery, parameter reads, homing), never around
/// the cycle's own frames or a stop's. <see cref="Raise"/> may be called from any thread, lock-free.
/// </summary>
public sealed class BusInterruption
{
    private volatile string? _reason;

    /// <summary>Why the work is being cut short; null while nothing asks for it.</summary>
    public string? Reason => _reason;

    /// <summary>True while raised.</summary>
    public bool IsRaised => _reason is not null;

    /// <summary>Cuts the work short at its next frame (any thread).</summary>
    public void Raise(string reason)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(reason);
        _reason = reason;
    }

    /// <summary>Lets work run again (the bus's owner, once the interrupted work has ended).</summary>
    public void Clear() => _reason = null;
}

/// <summary>Bus work was cut short before its next frame (<see cref="BusInterruption"/>): nothing more was sent.</summary>
public sealed class BusWorkInterruptedException : OperationCanceledException
{
    /// <summary>An interruption for <paramref name="reason"/>.</summary>
    public BusWorkInterruptedException(string reason)
        : base($"cut short before its next bus transaction: {reason}")
    {
    }

    /// <summary>An interruption with no reason given.</summary>
    public BusWorkInterruptedException()
        : base("cut short before its next bus transaction")
    {
    }

    /// <summary>An interruption wrapping <paramref name="inner"/>.</summary>
    public BusWorkInterruptedException(string message, Exception inner)
        : base(message, inner)
    {
    }
}
