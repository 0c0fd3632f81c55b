using RobotControl.WebConsole.Server;

namespace RobotControl.WebConsole.Tests.Server;

/// <summary>A stream client that reads slower than frames are cut loses its oldest frames; adding never waits.</summary>
public sealed class StreamQueueTests
{
    [Fact]
    public async Task A_full_queue_drops_the_oldest_frames_and_keeps_the_newest()
    {
        var queue = new FrameQueue(4);
        for (byte i = 0; i < 10; i++)
        {
            queue.Add([i]); // a client that has not read anything yet: never blocks
        }

        Assert.Equal(6, queue.Dropped);
        var kept = new List<byte>();
        for (var i = 0; i < 4; i++)
        {
            kept.Add((await queue.NextAsync(CancellationToken.None))[0]);
        }

        Assert.Equal(new byte[] { 6, 7, 8, 9 }, kept);
        queue.Add([10]);
        Assert.Equal(10, (await queue.NextAsync(CancellationToken.None))[0]);
        Assert.Equal(6, queue.Dropped);
    }
}
