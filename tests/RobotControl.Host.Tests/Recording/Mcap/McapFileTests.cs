using System.Text;
using RobotControl.Host.Recording.Mcap;

namespace RobotControl.Host.Tests.Recording.Mcap;

/// <summary>
/// The indexed reader: opened by its summary, it reads only the chunks a time range and the channels asked for may
/// hold, and gives messages in log-time order even where chunks overlap in time.
/// </summary>
public sealed class McapFileTests
{
    [Fact]
    public void A_time_range_reads_only_the_chunks_that_may_hold_it()
    {
        var path = Temp("ranged.mcap");
        using (var writer = new McapWriter(File.Create(path), string.Empty, "test", chunkBytes: 1024))
        {
            var a = writer.AddChannel(writer.AddSchema("A", "jsonschema", "{}"u8), "/a", "json");
            for (var i = 0; i < 1000; i++)
            {
                writer.WriteMessage(a, Ms(i), Encoding.UTF8.GetBytes($"{{\"x\":{i}}}"));
            }

            writer.Finish();
        }

        var bytes = File.ReadAllBytes(path);
        bytes[bytes.AsSpan().IndexOf("{\"x\":3}"u8) + 5] = (byte)'4'; // the first chunk is damaged
        File.WriteAllBytes(path, bytes);
        using var file = McapFile.Open(path);

        var late = file.Messages(fromNs: Ms(900), toNs: Ms(949)).ToList();

        Assert.True(file.Chunks.Count > 10, $"{file.Chunks.Count} chunks");
        Assert.Equal(50, late.Count);
        Assert.Equal(Ms(900), late[0].LogTimeNs);
        Assert.Equal("{\"x\":949}", Encoding.UTF8.GetString(late[^1].Data.Span));
        Assert.Contains("CRC", Assert.Throws<InvalidDataException>(() => file.Messages(toNs: Ms(10)).Count()).Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Messages_come_in_log_time_order_across_chunks_that_overlap_and_only_on_the_channels_asked_for()
    {
        var path = Temp("overlap.mcap");
        ushort a, b;
        using (var writer = new McapWriter(File.Create(path), string.Empty, "test", chunkBytes: 512))
        {
            a = writer.AddChannel(writer.AddSchema("A", "jsonschema", "{}"u8), "/a", "json");
            b = writer.AddChannel(writer.AddSchema("B", "jsonschema", "{}"u8), "/b", "json");
            for (var i = 0; i < 600; i++)
            {
                var late = i % 7 == 3; // a seventh of the messages arrive 40 ms late, into later chunks
                writer.WriteMessage(late ? b : a, Ms(late ? i - 40 : i), Encoding.UTF8.GetBytes($"{{\"i\":{i}}}"));
            }

            writer.Finish();
        }

        using var file = McapFile.Open(path);
        var all = file.Messages().Select(m => m.LogTimeNs).ToList();
        var onlyB = file.Messages([b]).ToList();

        Assert.Equal(600, all.Count);
        Assert.Equal(all.Order().ToList(), all);
        Assert.True(file.Chunks.Zip(file.Chunks.Skip(1)).Any(p => p.Second.StartNs < p.First.EndNs), "chunks overlap in time");
        Assert.All(onlyB, m => Assert.Equal(b, m.ChannelId));
        Assert.Equal(600 / 7 + 1, onlyB.Count);
        Assert.Equal((ulong)onlyB.Count, file.MessageCounts[b]);
        Assert.Equal(a, file.Channel("/a")!.Id);
    }

    [Fact]
    public void A_damaged_zstd_chunk_is_one_line_naming_the_chunk()
    {
        var path = Temp("zstd.mcap");
        using (var writer = new McapWriter(File.Create(path), string.Empty, "test", chunkBytes: 4096, compression: McapCompression.Zstd))
        {
            var a = writer.AddChannel(writer.AddSchema("A", "jsonschema", "{}"u8), "/a", "json");
            for (var i = 0; i < 2000; i++)
            {
                writer.WriteMessage(a, Ms(i), Encoding.UTF8.GetBytes($"{{\"x\":{i},\"y\":{i * 0.5}}}"));
            }

            writer.Finish();
        }

        long first;
        using (var intact = McapFile.Open(path))
        {
            Assert.Equal(2000, intact.Messages().Count());
            first = intact.Chunks[0].Offset;
        }

        var bytes = File.ReadAllBytes(path);
        bytes[first + 80] ^= 0x5A; // inside the first chunk's compressed records
        File.WriteAllBytes(path, bytes);
        using var damaged = McapFile.Open(path);

        var ex = Assert.Throws<InvalidDataException>(() => damaged.Messages().Count());

        Assert.StartsWith($"{path}: the chunk at byte {first}: ", ex.Message, StringComparison.Ordinal);
        Assert.Contains("damaged", ex.Message, StringComparison.Ordinal);
    }

    private static ulong Ms(int ms) => (ulong)ms * 1_000_000UL;

    private static string Temp(string name) => Path.Combine(Directory.CreateTempSubdirectory("rc-mcapfile-").FullName, name);
}
