using RobotControl.Bus.Protocol;

namespace RobotControl.Bus.Tests.Protocol;

public sealed class FrameCodecTests
{
    // Examples from the ROBOTIS Protocol 2.0 e-manual.
    [Theory]
    [InlineData(0x01, Instruction.Ping, "", "FF FF FD 00 01 03 00 01 19 4E")]
    [InlineData(0xFE, Instruction.Ping, "", "FF FF FD 00 FE 03 00 01 31 42")]
    [InlineData(0x01, Instruction.Read, "84 00 04 00", "FF FF FD 00 01 07 00 02 84 00 04 00 1D 15")]
    [InlineData(0x01, Instruction.Write, "74 00 00 02 00 00", "FF FF FD 00 01 09 00 03 74 00 00 02 00 00 CA 89")]
    [InlineData(0xFE, Instruction.SyncRead, "84 00 04 00 01 02", "FF FF FD 00 FE 09 00 82 84 00 04 00 01 02 CE FA")]
    public void Instruction_packets_match_the_reference_bytes(byte id, Instruction instruction, string parameters, string expected)
    {
        var buffer = new byte[64];
        var n = FrameEncoder.EncodeInstruction(buffer, id, instruction, Hex(parameters));
        Assert.Equal(Hex(expected), buffer[..n]);
    }

    [Fact]
    public void Status_packet_matches_the_reference_bytes_and_decodes()
    {
        var buffer = new byte[64];
        var n = FrameEncoder.EncodeStatus(buffer, 0x01, 0x00, Hex("06 04 26"));
        Assert.Equal(Hex("FF FF FD 00 01 07 00 55 00 06 04 26 65 5D"), buffer[..n]);

        var decoder = new FrameDecoder();
        Assert.True(decoder.Push(buffer.AsSpan(0, n), out var used));
        Assert.Equal(n, used);
        Assert.True(decoder.IsStatus);
        Assert.Equal(1, decoder.Id);
        Assert.Equal(0, decoder.Error);
        Assert.Equal(Hex("06 04 26"), decoder.Parameters.ToArray());
    }

    [Theory]
    [InlineData("FF FF FD")]
    [InlineData("01 FF FF FD 02")]
    [InlineData("FF FF FD FF FF FD")]
    [InlineData("FF FF FF FD FD")]
    public void Payloads_holding_the_header_pattern_are_stuffed_and_restored(string payload)
    {
        var parameters = Hex(payload);
        var buffer = new byte[64];
        var n = FrameEncoder.EncodeInstruction(buffer, 7, Instruction.Write, parameters);
        var body = buffer.AsSpan(8, n - 10);
        for (var i = 2; i < body.Length; i++)
        {
            if (body[i - 2] == 0xFF && body[i - 1] == 0xFF && body[i] == 0xFD)
            {
                Assert.True(i + 1 < body.Length && body[i + 1] == 0xFD, "every FF FF FD in the payload is followed by a stuffed FD");
            }
        }

        var decoder = new FrameDecoder();
        Assert.True(decoder.Push(buffer.AsSpan(0, n), out _));
        Assert.Equal(parameters, decoder.Parameters.ToArray());
        Assert.Equal((byte)Instruction.Write, decoder.Instruction);
    }

    [Fact]
    public void A_corrupted_frame_is_dropped_and_the_next_frame_in_the_stream_is_found()
    {
        var a = new byte[32];
        var na = FrameEncoder.EncodeStatus(a, 3, 0, Hex("10 20 30"));
        var b = new byte[32];
        var nb = FrameEncoder.EncodeStatus(b, 4, 0, Hex("40 50"));
        a[9] ^= 0x04; // flip one bit in the parameters
        var stream = Hex("00 13 FF").Concat(a[..na]).Concat(b[..nb]).ToArray();

        var decoder = new FrameDecoder();
        var frames = new List<byte>();
        var offset = 0;
        while (true)
        {
            var got = decoder.Push(stream.AsSpan(offset), out var used);
            offset += used;
            if (!got)
            {
                break;
            }

            frames.Add(decoder.Id);
        }

        Assert.Equal([4], frames);
        Assert.Equal(1, decoder.CrcErrors);
    }

    [Fact]
    public void A_corrupted_length_that_swallows_the_next_frame_still_yields_it()
    {
        var a = new byte[32];
        var na = FrameEncoder.EncodeStatus(a, 3, 0, Hex("10 20 30"));
        var b = new byte[32];
        var nb = FrameEncoder.EncodeStatus(b, 4, 0, Hex("40 50"));
        a[5] = (byte)(a[5] + nb); // the length now covers frame b as well
        var stream = a[..na].Concat(b[..nb]).ToArray();

        var decoder = new FrameDecoder();
        Assert.True(decoder.Push(stream, out var used));
        Assert.Equal(stream.Length, used);
        Assert.Equal(4, decoder.Id);
        Assert.False(decoder.Push(ReadOnlySpan<byte>.Empty, out _));
        Assert.Equal(1, decoder.CrcErrors);
    }

    [Fact]
    public void Frames_split_byte_by_byte_decode_the_same()
    {
        var buffer = new byte[64];
        var n = FrameEncoder.EncodeInstruction(buffer, 9, Instruction.SyncWrite, Hex("74 00 04 00 01 FF FF FD 00 02 01 02 03 04"));
        var decoder = new FrameDecoder();
        var completed = 0;
        for (var i = 0; i < n; i++)
        {
            if (decoder.Push(buffer.AsSpan(i, 1), out _))
            {
                completed++;
                Assert.Equal(n - 1, i);
            }
        }

        Assert.Equal(1, completed);
        Assert.Equal(Hex("74 00 04 00 01 FF FF FD 00 02 01 02 03 04"), decoder.Parameters.ToArray());
    }

    [Fact]
    public void Encoding_and_decoding_allocate_nothing()
    {
        var buffer = new byte[128];
        var parameters = Hex("74 00 04 00 01 FF FF FD 00 02 01 02 03 04");
        var decoder = new FrameDecoder();
        Run(); // warm up
        var before = GC.GetAllocatedBytesForCurrentThread();
        for (var i = 0; i < 1000; i++)
        {
            Run();
        }

        Assert.Equal(before, GC.GetAllocatedBytesForCurrentThread());

        void Run()
        {
            var n = FrameEncoder.EncodeInstruction(buffer, 9, Instruction.SyncWrite, parameters);
            Assert.True(decoder.Push(buffer.AsSpan(0, n), out _));
        }
    }

    internal static byte[] Hex(string text) =>
        text.Split(' ', StringSplitOptions.RemoveEmptyEntries).Select(h => Convert.ToByte(h, 16)).ToArray();
}
