using RobotControl.Bus.Protocol;
using static RobotControl.Bus.Tests.Protocol.FrameCodecTests;

namespace RobotControl.Bus.Tests.Protocol;

/// <summary>
/// The decoder's edges, with counts worked out by hand: how many bytes each call takes, how many are discarded and why,
/// the largest frame, and bodies that no encoder would write (an unstuffed FF FF FD at the end, a status packet without
/// its error byte). Frame a is a status of ID 3 with 10 20 30 (7 + 55, 00, 3 parameters + CRC 2 = 14 bytes), frame b a
/// status of ID 4 with 40 50 (13 bytes).
/// </summary>
public sealed class FrameDecoderEdgeTests
{
    private static readonly byte[] A = Status(3, "10 20 30");
    private static readonly byte[] B = Status(4, "40 50");

    [Fact]
    public void Back_to_back_frames_are_taken_one_call_each_and_never_past_the_frame_s_end()
    {
        Assert.Equal((14, 13), (A.Length, B.Length));
        var stream = A.Concat(B).ToArray();
        var decoder = new FrameDecoder();
        Assert.True(decoder.Push(stream, out var used));
        Assert.Equal((14, (byte)3), (used, decoder.Id));
        Assert.True(decoder.Push(stream.AsSpan(used), out var usedB));
        Assert.Equal((13, (byte)4), (usedB, decoder.Id));
        Assert.Equal((0, 0L, 0L, 0L), (decoder.Pending, decoder.DiscardedBytes, decoder.CrcErrors, decoder.FramingErrors));
    }

    [Fact]
    public void Bytes_before_a_header_are_counted_as_discarded_one_by_one()
    {
        var decoder = new FrameDecoder();
        Assert.True(decoder.Push(Hex("00 13 FF FD").Concat(A).ToArray(), out var used));
        Assert.Equal((18, 4L, (byte)3), (used, decoder.DiscardedBytes, decoder.Id)); // 00 13 FF FD are not FF FF FD 00
    }

    [Fact]
    public void A_length_below_three_is_a_framing_error_and_its_seven_header_bytes_are_discarded()
    {
        // Length 2 cannot hold an instruction and a CRC. Nothing in 'FF FD 00 07 02 00' starts a header.
        var decoder = new FrameDecoder();
        Assert.True(decoder.Push(Hex("FF FF FD 00 07 02 00").Concat(B).ToArray(), out var used));
        Assert.Equal((20, (byte)4), (used, decoder.Id));
        Assert.Equal((1L, 0L, 7L), (decoder.FramingErrors, decoder.CrcErrors, decoder.DiscardedBytes));
    }

    [Fact]
    public void The_largest_frame_decodes_and_a_length_one_byte_longer_is_a_framing_error()
    {
        // 1014 parameters of 01 (nothing to stuff): length field 1 + 1014 + 2 = 1017, 7 + 1017 = 1024 bytes = the buffer.
        var largest = new byte[FrameConstants.MaxFrameSize];
        var n = FrameEncoder.EncodeInstruction(largest, 1, Instruction.Write, Enumerable.Repeat((byte)1, 1014).ToArray());
        Assert.Equal(1024, n);
        var decoder = new FrameDecoder();
        Assert.True(decoder.Push(largest, out var used));
        Assert.Equal((1024, 1014), (used, decoder.Parameters.Length));

        // Length 1018 (FA 03): 1025 bytes would not fit.
        Assert.True(decoder.Push(Hex("FF FF FD 00 01 FA 03").Concat(B).ToArray(), out used));
        Assert.Equal((20, (byte)4, 1L, 7L), (used, decoder.Id, decoder.FramingErrors, decoder.DiscardedBytes));
    }

    [Fact]
    public void Pending_counts_the_bytes_held_and_reset_discards_them()
    {
        var decoder = new FrameDecoder();
        Assert.False(decoder.Push(A.AsSpan(0, 5), out var used));
        Assert.Equal((5, 5), (used, decoder.Pending));
        decoder.Reset();
        Assert.Equal((0, 5L), (decoder.Pending, decoder.DiscardedBytes));
        Assert.True(decoder.Push(B, out _));
        Assert.Equal((0, 5L, (byte)4), (decoder.Pending, decoder.DiscardedBytes, decoder.Id));
    }

    [Fact]
    public void A_body_ending_in_an_unstuffed_header_pattern_is_refused_although_its_crc_is_right()
    {
        // Instruction 03, parameters FF FF FD with no stuffing FD after them: no encoder writes this.
        var decoder = new FrameDecoder();
        Assert.False(decoder.Push(WithCrc("FF FF FD 00 01 06 00 03 FF FF FD"), out _));
        Assert.Equal(1L, decoder.CrcErrors);
    }

    [Fact]
    public void A_status_packet_without_its_error_byte_is_refused_although_its_crc_is_right()
    {
        var decoder = new FrameDecoder();
        Assert.False(decoder.Push(WithCrc("FF FF FD 00 01 03 00 55"), out _));
        Assert.Equal(1L, decoder.CrcErrors);
        Assert.True(decoder.Push(A, out _)); // and the next frame is read as usual
    }

    [Fact]
    public void Ff_fd_is_not_the_header_pattern_and_is_neither_stuffed_nor_expected_to_be()
    {
        // One FF then FD: only FF FF FD gets the stuffing FD. Length field 1 + 2 + 2 = 5, frame 7 + 5 = 12 bytes.
        var frame = new byte[16];
        var n = FrameEncoder.EncodeInstruction(frame, 1, Instruction.Write, Hex("FF FD"));
        Assert.Equal(12, n);
        Assert.Equal(Hex("05 00 03 FF FD"), frame[5..10]);
        var decoder = new FrameDecoder();
        Assert.True(decoder.Push(frame.AsSpan(0, n), out _));
        Assert.Equal(Hex("FF FD"), decoder.Parameters.ToArray());
    }

    private static byte[] Status(byte id, string parameters)
    {
        var buffer = new byte[32];
        return buffer[..FrameEncoder.EncodeStatus(buffer, id, 0, Hex(parameters))];
    }

    /// <summary>Hand-written frame bytes (header to body) followed by their CRC.</summary>
    private static byte[] WithCrc(string body)
    {
        var bytes = Hex(body);
        var crc = Crc16.Compute(bytes);
        return [.. bytes, (byte)crc, (byte)(crc >> 8)];
    }
}
