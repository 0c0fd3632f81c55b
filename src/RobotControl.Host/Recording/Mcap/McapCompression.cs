namespace RobotControl.Host.Recording.Mcap;

/// <summary>The chunk compressions this project reads and writes: none (<c>""</c>).</summary>
internal static class McapCompression
{
    /// <summary>The records of a chunk compressed with <paramref name="compression"/>; <paramref name="unsupported"/> makes the error for one not read here.</summary>
    public static ReadOnlyMemory<byte> Decompress(string compression, ReadOnlyMemory<byte> data, ulong size, Func<Exception> unsupported) => compression switch
    {
        "" => data,
        _ => throw unsupported(),
    };
}
