using ZstdSharp;

namespace RobotControl.Host.Recording.Mcap;

/// <summary>
/// The chunk compressions this project writes and reads: none (<c>""</c>) and <c>zstd</c> (ZstdSharp, a managed port
/// of the reference library), the one every MCAP reader knows. One instance per writing thread (it keeps its
/// compressor and its output buffer).
/// </summary>
public sealed class McapCompression : IDisposable
{
    /// <summary>Chunks as they are.</summary>
    public const string None = "";

    /// <summary>Chunks compressed with zstd.</summary>
    public const string Zstd = "zstd";

    private readonly Compressor? _compressor;
    private byte[] _output = [];

    /// <summary>A compressor for <paramref name="name"/> (<see cref="None"/> or <see cref="Zstd"/>) at zstd level <paramref name="level"/>.</summary>
    /// <exception cref="ArgumentException">Another compression.</exception>
    public McapCompression(string name, int level = 1)
    {
        ArgumentNullException.ThrowIfNull(name);
        Name = name switch
        {
            None or Zstd => name,
            _ => throw new ArgumentException($"chunk compression '{name}': give '' or 'zstd'", nameof(name)),
        };
        _compressor = name == Zstd ? new Compressor(level) : null;
    }

    /// <summary>The compression's name, as a chunk record carries it.</summary>
    public string Name { get; }

    /// <summary><paramref name="records"/> compressed (valid until the next call), or themselves when uncompressed.</summary>
    public ReadOnlySpan<byte> Compress(ReadOnlySpan<byte> records)
    {
        if (_compressor is null)
        {
            return records;
        }

        var bound = Compressor.GetCompressBound(records.Length);
        if (_output.Length < bound)
        {
            _output = new byte[bound];
        }

        return _output.AsSpan(0, _compressor.Wrap(records, _output));
    }

    /// <summary>
    /// The records of a chunk compressed with <paramref name="compression"/>, <paramref name="size"/> bytes
    /// uncompressed; <paramref name="problem"/> makes the error that names the chunk from what is wrong with it (a
    /// compression not read here, bytes that do not decompress to its size).
    /// </summary>
    public static ReadOnlyMemory<byte> Decompress(string compression, ReadOnlyMemory<byte> data, ulong size, Func<string, Exception> problem)
    {
        ArgumentNullException.ThrowIfNull(problem);
        switch (compression)
        {
            case None:
                return data;
            case Zstd:
                var records = new byte[checked((int)size)];
                using (var decompressor = new Decompressor())
                {
                    try
                    {
                        if (decompressor.Unwrap(data.Span, records) != records.Length)
                        {
                            throw problem("its zstd data decompresses to fewer bytes than its size (the file is damaged)");
                        }
                    }
                    catch (ZstdException ex)
                    {
                        throw problem($"its zstd data does not decompress ({ex.Message}; the file is damaged)");
                    }
                }

                return records;
            default:
                throw problem($"it is compressed with '{compression}', which robotctl does not read (it reads uncompressed and zstd chunks)");
        }
    }

    /// <inheritdoc />
    public void Dispose() => _compressor?.Dispose();
}
