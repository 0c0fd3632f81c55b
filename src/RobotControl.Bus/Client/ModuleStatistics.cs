namespace RobotControl.Bus.Client;

/// <summary>
/// Traffic counters of one module ID, updated by the thread running the bus and readable from any thread (each
/// counter is read atomically; the set as a whole may be one frame apart).
/// </summary>
public sealed class ModuleStatistics
{
    private long _framesSent;
    private long _framesReceived;
    private long _crcErrors;
    private long _timeouts;
    private long _retries;
    private long _errorReplies;
    private long _lateReplies;
    private long _latencyTicksSum;
    private long _latencyCount;
    private long _latencyTicksMax;
    private long _latencyTicksLast;

    internal ModuleStatistics(byte id, long timestampFrequency)
    {
        Id = id;
        TimestampFrequency = timestampFrequency;
    }

    /// <summary>The module ID.</summary>
    public byte Id { get; }

    /// <summary>Frames addressed to this module (sync frames count once per module they carry).</summary>
    public long FramesSent => Volatile.Read(ref _framesSent);

    /// <summary>Valid status frames received from this module.</summary>
    public long FramesReceived => Volatile.Read(ref _framesReceived);

    /// <summary>Replies expected from this module that arrived with a bad CRC.</summary>
    public long CrcErrors => Volatile.Read(ref _crcErrors);

    /// <summary>Replies that did not arrive in time.</summary>
    public long Timeouts => Volatile.Read(ref _timeouts);

    /// <summary>Requests sent again after a timeout or corrupted reply.</summary>
    public long Retries => Volatile.Read(ref _retries);

    /// <summary>Replies whose error byte was non-zero.</summary>
    public long ErrorReplies => Volatile.Read(ref _errorReplies);

    /// <summary>Status frames from this module that came after their request was given up on, or answered another request.</summary>
    public long LateReplies => Volatile.Read(ref _lateReplies);

    /// <summary>Mean request-to-reply latency.</summary>
    public TimeSpan MeanLatency
    {
        get
        {
            var n = Volatile.Read(ref _latencyCount);
            return n == 0 ? TimeSpan.Zero : ToTimeSpan(Volatile.Read(ref _latencyTicksSum) / n);
        }
    }

    /// <summary>Largest request-to-reply latency.</summary>
    public TimeSpan MaxLatency => ToTimeSpan(Volatile.Read(ref _latencyTicksMax));

    /// <summary>Latency of the last reply.</summary>
    public TimeSpan LastLatency => ToTimeSpan(Volatile.Read(ref _latencyTicksLast));

    private long TimestampFrequency { get; }

    /// <inheritdoc />
    public override string ToString() =>
        $"id {Id}: sent {FramesSent}, received {FramesReceived}, crc errors {CrcErrors}, timeouts {Timeouts}, retries {Retries}, late replies {LateReplies}, error replies {ErrorReplies}, latency mean {MeanLatency.TotalMicroseconds:F0} us max {MaxLatency.TotalMicroseconds:F0} us";

    internal void Sent() => Interlocked.Increment(ref _framesSent);

    internal void Received(long latencyTicks)
    {
        Interlocked.Increment(ref _framesReceived);
        Interlocked.Add(ref _latencyTicksSum, latencyTicks);
        Interlocked.Increment(ref _latencyCount);
        Volatile.Write(ref _latencyTicksLast, latencyTicks);
        if (latencyTicks > Volatile.Read(ref _latencyTicksMax))
        {
            Volatile.Write(ref _latencyTicksMax, latencyTicks);
        }
    }

    internal void CrcError() => Interlocked.Increment(ref _crcErrors);

    internal void Timeout() => Interlocked.Increment(ref _timeouts);

    internal void Retry() => Interlocked.Increment(ref _retries);

    internal void ErrorReply() => Interlocked.Increment(ref _errorReplies);

    internal void LateReply() => Interlocked.Increment(ref _lateReplies);

    private TimeSpan ToTimeSpan(long ticks) => TimeSpan.FromTicks(ticks * TimeSpan.TicksPerSecond / TimestampFrequency);
}
