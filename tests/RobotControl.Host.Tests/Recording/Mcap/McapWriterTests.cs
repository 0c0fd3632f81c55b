using System.Text;
using RobotControl.Host.Recording.Mcap;
using RobotControl.TestSupport.Mcap;

namespace RobotControl.Host.Tests.Recording.Mcap;

/// <summary>
/// The project's MCAP writer against the official reader (<c>@mcap/core</c>, through <see cref="McapCheck"/>) and the
/// project's own reader: counts per channel, schemas, CRCs (chunk, data section, summary), a file cut short, a damaged one.
/// </summary>
public sealed class McapWriterTests
{
    [Fact]
    public void Crc32_is_the_ieee_crc_of_the_check_string()
    {
        Assert.Equal(0xCBF43926u, Crc32.Compute("123456789"u8));
    }

    [Theory]
    [InlineData(McapCompression.None)]
    [InlineData(McapCompression.Zstd)]
    public void The_official_reader_counts_every_channel_as_the_writer_did_and_every_crc_checks(string compression)
    {
        var path = Temp("complete.mcap");
        var counts = Write(path, messages: 3000, out _, compression);

        var check = McapCheck.Read(path);

        Assert.Null(check.Error);
        Assert.True(check.Complete);
        Assert.Equal(counts, check.StreamCounts);
        Assert.Equal(counts, check.IndexedCounts);
        Assert.Equal(counts, check.StatisticsCounts);
        Assert.True(check.DataSectionCrcOk);
        Assert.Equal(2, check.Schemas);
        Assert.Equal(0, check.BadJson);
        Assert.True(check.Chunks > 3, $"{check.Chunks} chunks");
        Assert.Equal(["robot.json"], check.Attachments);
        Assert.Equal([compression], check.Compressions);
        using var own = McapFile.Open(path);
        Assert.True(own.Complete);
        Assert.True(own.Indexed);
        Assert.Equal(counts, own.Messages().GroupBy(m => own.Channels[m.ChannelId].Topic).ToDictionary(g => g.Key, g => (long)g.Count()));
        Assert.Equal(counts, own.MessageCounts.ToDictionary(p => own.Channels[p.Key].Topic, p => (long)p.Value));
        Assert.Equal("{\"arm\":\"right\"}", own.Attachments["robot.json"]);
        Assert.Equal("1", own.Metadata["run"]["seed"]);
    }

    [Fact]
    public void A_file_cut_inside_a_chunk_reads_up_to_the_last_complete_chunk_with_both_readers()
    {
        var path = Temp("cut.mcap");
        Write(path, messages: 3000, out var chunkEnds);
        var bytes = File.ReadAllBytes(path);
        var (end, messagesBefore) = chunkEnds[2];
        File.WriteAllBytes(path, bytes[..(int)(end + 100)]); // 100 bytes into the fourth chunk

        var check = McapCheck.Read(path);
        using var own = McapFile.Open(path);

        Assert.Null(check.Error);
        Assert.False(check.Complete);
        Assert.Equal(messagesBefore, check.StreamCounts.Values.Sum());
        Assert.Equal(messagesBefore, own.Messages().LongCount());
        Assert.Equal(messagesBefore, (long)own.MessageCount);
        Assert.False(own.Indexed);
        Assert.False(own.Complete);
        Assert.Contains("cut short", own.Truncated, StringComparison.Ordinal);
    }

    [Fact]
    public void A_flipped_byte_inside_a_chunk_fails_the_chunk_crc_in_both_readers()
    {
        var path = Temp("damaged.mcap");
        Write(path, messages: 300, out _);
        var bytes = File.ReadAllBytes(path);
        bytes[bytes.AsSpan().IndexOf("{\"x\":5}"u8) + 5] = (byte)'6'; // a message inside the first chunk: still JSON, another value
        File.WriteAllBytes(path, bytes);

        Assert.Contains("Incorrect chunk CRC", McapCheck.Read(path).Error, StringComparison.Ordinal);
        using var damaged = McapFile.Open(path); // opened by its summary: the chunk is checked when it is read
        var ex = Assert.Throws<InvalidDataException>(() => damaged.Messages().Count());
        Assert.Contains("CRC", ex.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void A_file_that_is_not_mcap_is_one_line_naming_it()
    {
        var path = Temp("report.json");
        File.WriteAllText(path, "{\"ticks\": 1}");

        var ex = Assert.Throws<InvalidDataException>(() => McapFile.Open(path));

        Assert.Equal($"{path}: not an MCAP file (it does not start with the MCAP magic)", ex.Message);
    }

    private static string Temp(string name) => Path.Combine(Directory.CreateTempSubdirectory("rc-mcap-").FullName, name);

    /// <summary>Writes two JSON channels (two messages on one for every one on the other) in small chunks; returns the counts per topic and, per chunk, where it ended and the messages before that.</summary>
    private static Dictionary<string, long> Write(string path, int messages, out List<(long End, long MessagesBefore)> chunkEnds, string compression = McapCompression.None)
    {
        chunkEnds = [];
        using var writer = new McapWriter(File.Create(path), string.Empty, "test", chunkBytes: 4096, compression: compression);
        writer.AddMetadata("run", new Dictionary<string, string> { ["seed"] = "1" });
        writer.AddAttachment("robot.json", "application/json", "{\"arm\":\"right\"}"u8, 0);
        var a = writer.AddChannel(writer.AddSchema("A", "jsonschema", "{\"type\":\"object\"}"u8), "/a", "json");
        var b = writer.AddChannel(writer.AddSchema("B", "jsonschema", "{\"type\":\"object\",\"properties\":{\"x\":{\"type\":\"number\"}}}"u8), "/b", "json");
        var chunks = 0;
        for (var i = 0; i < messages; i++)
        {
            writer.WriteMessage(i % 3 == 2 ? b : a, (ulong)i * 1_000_000UL, Encoding.UTF8.GetBytes($"{{\"x\":{i}}}"));
            if (writer.ChunkCount > chunks)
            {
                chunks = writer.ChunkCount;
                chunkEnds.Add((writer.Position, i + 1));
            }
        }

        writer.Finish();
        return writer.CountsByTopic.ToDictionary(p => p.Key, p => (long)p.Value);
    }
}
