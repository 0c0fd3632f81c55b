using RobotControl.Host.Recording.Mcap;

namespace RobotControl.Host.Recording;

/// <summary>What a session recording does (<c>--record</c>).</summary>
public sealed record RecordingOptions
{
    /// <summary>The MCAP file to write.</summary>
    public required string Path { get; init; }

    /// <summary>
    /// The graph's signals, the input devices and the tool poses are recorded every this many ticks (1: at the loop
    /// rate); joints are recorded every tick, the run levels, trips and commands as they happen, the bus and the
    /// modules every <see cref="SlowEvery"/>.
    /// </summary>
    public int Decimate { get; init; } = 1;

    /// <summary>The chunks' compression: <see cref="McapCompression.Zstd"/> (a file about a tenth of the size) or <see cref="McapCompression.None"/>.</summary>
    public string Compression { get; init; } = McapCompression.Zstd;

    /// <summary>How often (loop time) the bus statistics and module status are recorded.</summary>
    public TimeSpan SlowEvery { get; init; } = TimeSpan.FromMilliseconds(100);

    /// <summary>Rows the loop can get ahead of the writer before it drops them (counted).</summary>
    public int RingRows { get; init; } = 8192;

    /// <summary>Opens the file's stream (tests give a stream that fills up); null: a new file at <see cref="Path"/>.</summary>
    public Func<string, Stream>? OpenStream { get; init; }

    /// <summary>Called once, on the writer thread, when the recording stops early (a full disk): one line naming the file and why.</summary>
    public Action<string>? Stopped { get; init; }
}
