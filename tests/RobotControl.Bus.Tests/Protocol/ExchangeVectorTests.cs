using System.Text.Json;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Tests.Support;

using RobotControl.TestSupport;

namespace RobotControl.Bus.Tests.Protocol;

/// <summary>
/// The host codec and status-error reading against the shared request/reply exchanges of
/// firmware/protocol/test-vectors.json (the firmware's test_exchanges runs the same steps on the real module).
/// </summary>
public sealed class ExchangeVectorTests
{
    public static TheoryData<string> ExchangeNames()
    {
        var data = new TheoryData<string>();
        foreach (var x in Load())
        {
            data.Add(x.GetProperty("name").GetString()!);
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(ExchangeNames))]
    public void Every_step_decodes_and_its_error_is_the_one_described(string name)
    {
        var x = Load().Single(e => e.GetProperty("name").GetString() == name);
        var description = x.GetProperty("description").GetString()!;
        foreach (var step in x.GetProperty("steps").EnumerateArray())
        {
            var request = new FrameDecoder();
            Assert.True(request.Push(FrameCodecTests.Hex(step.GetProperty("request_hex").GetString()!), out _), $"{name}: request");
            Assert.False(request.IsStatus);

            var replyHex = step.GetProperty("reply_hex").GetString()!;
            if (replyHex.Length == 0)
            {
                Assert.Equal(FrameConstants.BroadcastId, request.Id); // only broadcasts go unanswered
                continue;
            }

            var reply = new FrameDecoder();
            Assert.True(reply.Push(FrameCodecTests.Hex(replyHex), out _), $"{name}: reply");
            Assert.True(reply.IsStatus);
            Assert.Equal(request.Id == FrameConstants.BroadcastId ? reply.Id : request.Id, reply.Id);
            var error = StatusErrors.Number(reply.Error);
            if (error != StatusError.None)
            {
                var text = StatusErrors.Describe(reply.Error);
                Assert.Contains(text[5..], description, StringComparison.Ordinal); // e.g. "access error"
                Assert.Contains($"0x{(byte)error:X2}", description, StringComparison.Ordinal);
                var fast = request.Instruction is (byte)Instruction.FastSyncRead or (byte)Instruction.FastBulkRead;
                if (fast)
                {
                    Assert.NotEqual(0, reply.Parameters.Length); // a fast read part keeps its place
                }
                else
                {
                    // A refused read carries the requested length of zero bytes (as ROBOTIS devices answer); any
                    // other refused request no data.
                    Assert.Equal(RequestedLength(request, reply.Id), reply.Parameters.Length);
                    Assert.All(reply.Parameters.ToArray(), b => Assert.Equal(0, b));
                }
            }
        }
    }

    [Fact]
    public void Every_protocol_error_number_is_covered_by_an_exchange()
    {
        var seen = new HashSet<StatusError>();
        foreach (var step in Load().SelectMany(x => x.GetProperty("steps").EnumerateArray()))
        {
            var hex = step.GetProperty("reply_hex").GetString()!;
            var d = new FrameDecoder();
            if (hex.Length > 0 && d.Push(FrameCodecTests.Hex(hex), out _))
            {
                seen.Add(StatusErrors.Number(d.Error));
            }
        }

        // 0x03 (CRC) is never sent: a corrupted frame is dropped, its ID cannot be trusted.
        var expected = Enum.GetValues<StatusError>().Where(e => e != StatusError.Crc);
        Assert.All(expected, e => Assert.Contains(e, seen));
    }

    [Theory]
    [InlineData(0x00, "0x00 no error")]
    [InlineData(0x87, "0x07 access error (alert)")]
    [InlineData(0x04, "0x04 data range error")]
    [InlineData(0x06, "0x06 data limit error")]
    public void Describe_names_the_number_and_the_alert(byte errorByte, string expected) =>
        Assert.Equal(expected, StatusErrors.Describe(errorByte));

    /// <summary>The data length <paramref name="request"/> asks module <paramref name="id"/> for (0: not a read, or a read without its length).</summary>
    private static int RequestedLength(FrameDecoder request, byte id)
    {
        var p = request.Parameters;
        switch ((Instruction)request.Instruction)
        {
            case Instruction.Read or Instruction.SyncRead when p.Length >= 4:
                return System.Buffers.Binary.BinaryPrimitives.ReadUInt16LittleEndian(p[2..]);
            case Instruction.BulkRead:
                for (var o = 0; o + 5 <= p.Length; o += 5)
                {
                    if (p[o] == id)
                    {
                        return System.Buffers.Binary.BinaryPrimitives.ReadUInt16LittleEndian(p[(o + 3)..]);
                    }
                }

                return -1;
            default:
                return 0;
        }
    }

    private static JsonElement[] Load()
    {
        using var doc = JsonDocument.Parse(File.ReadAllText(RepositoryPaths.Firmware("protocol/test-vectors.json")));
        return doc.RootElement.GetProperty("exchanges").EnumerateArray().Select(e => e.Clone()).ToArray();
    }
}
