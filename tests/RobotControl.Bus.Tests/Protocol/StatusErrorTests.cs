using RobotControl.Bus.Protocol;

namespace RobotControl.Bus.Tests.Protocol;

/// <summary>The status error texts, as docs/protocol.md names the error numbers.</summary>
public sealed class StatusErrorTests
{
    [Theory]
    [InlineData(0x00, "0x00 no error")]
    [InlineData(0x01, "0x01 result fail")]
    [InlineData(0x02, "0x02 instruction error")]
    [InlineData(0x03, "0x03 CRC error")]
    [InlineData(0x04, "0x04 data range error")]
    [InlineData(0x05, "0x05 data length error")]
    [InlineData(0x06, "0x06 data limit error")]
    [InlineData(0x07, "0x07 access error")]
    [InlineData(0x08, "0x08 unknown error")]
    [InlineData(0x87, "0x07 access error (alert)")]
    [InlineData(0x80, "0x00 no error (alert)")]
    public void Each_error_number_is_described_with_its_name_and_the_alert_bit(byte errorByte, string text) =>
        Assert.Equal(text, StatusErrors.Describe(errorByte));
}
