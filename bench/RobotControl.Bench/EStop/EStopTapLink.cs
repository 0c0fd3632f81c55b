using System.Diagnostics;
using RobotControl.Bus.Transports;

namespace RobotControl.Bench.EStop;

/// <summary>
/// Wraps the host's end of the bus: timestamps (<see cref="Stopwatch"/>, on the wall clock, when the host's Write is
/// called) every goal SYNC WRITE (the start of a bus cycle) and, once armed with a request's arrival, the first frame
/// at or after it that is a stop frame of the wanted kind (<see cref="EStopFrameDetector"/>). Written on the bus thread;
/// <see cref="Arm"/> and <see cref="TryTake"/> from any thread.
/// </summary>
internal sealed class EStopTapLink(IByteLink inner, TimeProvider clock) : IByteLink, IClockedLink
{
    private readonly EStopFrameDetector _detector = new();
    private readonly List<long> _cycleStarts = new(1 << 20);
    private readonly Lock _cycleGate = new();
    private long _armedAt;
    private long _arrivedAt;
    private long _firstAt;
    private int _firstKind;

    /// <summary>The frame that ends a stop's measurement: <see cref="StopFrame.TorqueOff"/> or <see cref="StopFrame.Hold"/>.</summary>
    public StopFrame Wanted { get; set; } = StopFrame.TorqueOff;

    public string Description => inner.Description;

    public int BaudRate => inner.BaudRate;

    public TimeProvider Clock => clock;

    /// <summary>From <paramref name="arrival"/> (a <see cref="Stopwatch"/> timestamp) on, the next wanted frame is recorded.</summary>
    public void Arm(long arrival)
    {
        Volatile.Write(ref _arrivedAt, arrival);
        Volatile.Write(ref _firstAt, 0);
        Volatile.Write(ref _armedAt, arrival);
    }

    /// <summary>The arrival given to the last <see cref="Arm"/>.</summary>
    public long ArrivedAt => Volatile.Read(ref _arrivedAt);

    /// <summary>The first wanted frame since <see cref="Arm"/>: its timestamp and kind; false while none.</summary>
    public bool TryTake(out long at, out StopFrame kind)
    {
        at = Volatile.Read(ref _firstAt);
        kind = (StopFrame)Volatile.Read(ref _firstKind);
        return at != 0;
    }

    /// <summary>The goal SYNC WRITE timestamps from <paramref name="from"/> on (a copy).</summary>
    public long[] CycleStartsSince(long from)
    {
        lock (_cycleGate)
        {
            return [.. _cycleStarts.Where(t => t >= from)];
        }
    }

    public void Write(ReadOnlySpan<byte> data)
    {
        var now = Stopwatch.GetTimestamp();
        var kind = _detector.Classify(data);
        if (kind is StopFrame.Goals or StopFrame.Hold)
        {
            lock (_cycleGate)
            {
                _cycleStarts.Add(now);
            }
        }

        var armed = Volatile.Read(ref _armedAt);
        if (armed != 0 && now >= armed && kind == Wanted && Volatile.Read(ref _firstAt) == 0)
        {
            Volatile.Write(ref _firstKind, (int)kind);
            Volatile.Write(ref _firstAt, now);
            Volatile.Write(ref _armedAt, 0);
        }

        inner.Write(data);
    }

    public int Read(Span<byte> buffer, TimeSpan timeout) => inner.Read(buffer, timeout);

    public void DiscardInput() => inner.DiscardInput();

    public void Dispose() => inner.Dispose();
}
