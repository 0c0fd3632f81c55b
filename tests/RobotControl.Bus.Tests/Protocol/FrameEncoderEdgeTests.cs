using RobotControl.Bus.Protocol;
using static RobotControl.Bus.Tests.Protocol.FrameCodecTests;

namespace RobotControl.Bus.Tests.Protocol;

/// <summary>
/// The encoder's destination checks: a destination of exactly the frame's length works, and every shorter one is
/// refused with <see cref="ArgumentException"/> before a byte is written past it (never an index error).
/// </summary>
public sealed class FrameEncoderEdgeTests
{
    [Theory]
    [InlineData(false, "01 02 03 04 05 06", 16)] // 10 + 6
    [InlineData(true, "01 02 03 04 05 06", 17)] // 10 + error byte + 6
    [InlineData(false, "01 FF FF FD 02", 16)] // 10 + 5 + the stuffing FD
    [InlineData(false, "01 02 FF FF FD", 16)] // the stuffing FD is the last byte before the CRC
    [InlineData(true, "FF FF FD FF FF FD", 19)] // 10 + error byte + 6 + two stuffing FDs
    public void A_destination_of_exactly_the_frame_s_length_works_and_every_shorter_one_is_refused(bool status, string parameters, int length)
    {
        var p = Hex(parameters);
        var exact = new byte[length];
        Assert.Equal(length, Encode(exact, status, p));
        for (var size = 0; size < length; size++)
        {
            var small = new byte[size];
            var error = Record.Exception(() => Encode(small, status, p));
            Assert.True(error is ArgumentException { ParamName: "dest" }, $"{size} bytes: {error?.GetType().Name ?? "no exception"}");
        }
    }

    private static int Encode(byte[] destination, bool status, byte[] parameters) => status
        ? FrameEncoder.EncodeStatus(destination, 7, 0, parameters)
        : FrameEncoder.EncodeInstruction(destination, 7, Instruction.Write, parameters);
}
