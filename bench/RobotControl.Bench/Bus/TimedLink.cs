using System.Diagnostics;
using RobotControl.Bus.Transports;

namespace RobotControl.Bench.Bus;

/// <summary>Wraps a link and adds up the wall time spent inside it (on the virtual bus: the simulation's share).</summary>
internal sealed class TimedLink(IByteLink inner) : IByteLink, IClockedLink
{
    public long InsideTicks { get; private set; }

    public string Description => inner.Description;

    public int BaudRate => inner.BaudRate;

    public TimeProvider Clock => ((IClockedLink)inner).Clock;

    public void Write(ReadOnlySpan<byte> data)
    {
        var t = Stopwatch.GetTimestamp();
        inner.Write(data);
        InsideTicks += Stopwatch.GetTimestamp() - t;
    }

    public int Read(Span<byte> buffer, TimeSpan timeout)
    {
        var t = Stopwatch.GetTimestamp();
        var n = inner.Read(buffer, timeout);
        InsideTicks += Stopwatch.GetTimestamp() - t;
        return n;
    }

    public void DiscardInput() => inner.DiscardInput();

    public void Dispose() => inner.Dispose();
}
