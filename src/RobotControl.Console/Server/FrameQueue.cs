using System.Threading.Channels;

namespace RobotControl.WebConsole.Server;

/// <summary>
/// The frames cut for one stream client and not sent yet: at most <c>capacity</c>; a new frame pushes the oldest out
/// when the client reads slower than frames are cut. Adding never waits, so a slow client never holds up the one who
/// cuts the frames (nor anything else); it only loses its oldest frames, counted in <see cref="Dropped"/>.
/// </summary>
internal sealed class FrameQueue
{
    private readonly Channel<byte[]> _frames;
    private long _dropped;

    /// <summary>A queue of at most <paramref name="capacity"/> frames.</summary>
    public FrameQueue(int capacity)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(capacity, 1);
        _frames = Channel.CreateBounded<byte[]>(
            new BoundedChannelOptions(capacity) { FullMode = BoundedChannelFullMode.DropOldest, SingleReader = true, SingleWriter = true },
            _ => Interlocked.Increment(ref _dropped));
    }

    /// <summary>Frames pushed out before they were sent.</summary>
    public long Dropped => Interlocked.Read(ref _dropped);

    /// <summary>Adds a serialized frame (never waits).</summary>
    public void Add(byte[] frame) => _frames.Writer.TryWrite(frame);

    /// <summary>The next frame to send, waiting for one.</summary>
    public ValueTask<byte[]> NextAsync(CancellationToken token) => _frames.Reader.ReadAsync(token);
}
