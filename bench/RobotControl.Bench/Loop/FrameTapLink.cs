using RobotControl.Bus.Transports;

namespace RobotControl.Bench.Loop;

/// <summary>Passes bytes through to the virtual bus and timestamps every sync-write frame the host sends.</summary>
internal sealed class FrameTapLink(IByteLink inner, TimeProvider clock) : IByteLink, IClockedLink
{
    private const byte SyncWrite = 0x83;

    public List<(long Timestamp, int Bytes)> SyncWrites { get; } = new(1 << 16);

    public string Description => inner.Description;

    public int BaudRate => inner.BaudRate;

    public TimeProvider Clock => clock;

    public void Write(ReadOnlySpan<byte> data)
    {
        // Dynamixel 2.0: FF FF FD 00 id len_l len_h instruction ...
        if (data.Length > 7 && data[0] == 0xFF && data[1] == 0xFF && data[2] == 0xFD && data[7] == SyncWrite)
        {
            SyncWrites.Add((clock.GetTimestamp(), data.Length));
        }

        inner.Write(data);
    }

    public int Read(Span<byte> buffer, TimeSpan timeout) => inner.Read(buffer, timeout);

    public void DiscardInput() => inner.DiscardInput();

    public void Dispose() => inner.Dispose();
}
