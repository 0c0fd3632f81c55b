using RobotControl.Host.Recording;
using RobotControl.Host.Recording.Mcap;
using RobotControl.Runtime.GraphFiles;
using RobotControl.TestSupport;

namespace RobotControl.Host.Tests.Recording;

/// <summary>
/// The writer thread's encoding of a loop row: once warm, a row (the joints, the graph, the devices, the poses and the
/// link frames) allocates nothing, so the writer adds little garbage for the runtime to collect beside the loop. What
/// remains is per chunk (its index entries; and zstd's compressor, about 17 KB per chunk of ~150 rows in ZstdSharp).
/// </summary>
public sealed class RecordingChannelsTests
{
    [Theory]
    [InlineData(McapCompression.None, 16)]
    [InlineData(McapCompression.Zstd, 128)]
    public void A_row_allocates_nothing_once_the_writer_is_warm_only_its_chunks_do(string compression, double bytesPerRow)
    {
        var loaded = GraphFile.Load(Graphs.Path("teleop-lb.json"), TestPlugins.Catalog(), TimeProvider.System);
        var layout = new RecordingLayout(loaded);
        var row = new double[layout.Width];
        using var writer = new McapWriter(Stream.Null, string.Empty, "test", compression: compression);
        using var channels = new RecordingChannels(writer, layout, [1, 2, 3]);
        void Rows(ulong from, ulong count)
        {
            for (var tick = from; tick < from + count; tick++)
            {
                for (var i = 0; i < row.Length; i++)
                {
                    row[i] = Math.Sin((tick * 0.001) + i);
                }

                channels.WriteRow(row, tick * 1_000_000UL, full: true, links: tick % 10 == 0);
            }
        }

        Rows(0, 2000); // warm: the buffers have grown to a chunk's size, the code is compiled
        var before = GC.GetAllocatedBytesForCurrentThread();
        Rows(2000, 10_000);
        var perRow = (GC.GetAllocatedBytesForCurrentThread() - before) / 10_000.0;

        Assert.True(perRow < bytesPerRow, $"{perRow:F1} bytes a row"); // the chunk's, shared by its ~150 rows
    }
}
