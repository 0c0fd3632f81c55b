namespace RobotControl.Plugins.Link.Tests;

public sealed class FrameRingTests
{
    [Fact]
    public void Frames_come_out_oldest_first()
    {
        var ring = new FrameRing(frameLength: 2, capacity: 4);
        Push(ring, 1);
        Push(ring, 2);
        var frame = new byte[2];

        Assert.True(ring.TryRead(frame));
        Assert.Equal(1, frame[0]);
        Assert.True(ring.TryRead(frame));
        Assert.Equal(2, frame[0]);
        Assert.False(ring.TryRead(frame));
        Assert.Equal(0, ring.Dropped);
    }

    [Fact]
    public void A_full_ring_overwrites_the_oldest_and_counts_it()
    {
        var ring = new FrameRing(frameLength: 2, capacity: 4);
        for (byte i = 1; i <= 10; i++)
        {
            Push(ring, i);
        }

        Assert.Equal(6, ring.Dropped); // counted already while the consumer is away
        var frame = new byte[2];
        var read = new List<byte>();
        while (ring.TryRead(frame))
        {
            read.Add(frame[0]);
        }

        Assert.Equal([7, 8, 9, 10], read);
        Assert.Equal(6, ring.Dropped);
    }

    private static void Push(FrameRing ring, byte value)
    {
        var slot = ring.BeginWrite();
        slot[0] = value;
        slot[1] = value;
        ring.EndWrite();
    }
}
