using RobotControl.CoppeliaSim.Protocol;

namespace RobotControl.CoppeliaSim.Tests.Protocol;

/// <summary>Request encodings against bytes derived by hand from RFC 8949 (major type in the top 3 bits, length in the low 5).</summary>
public sealed class RemoteApiCodecTests
{
    [Fact]
    public void Sim_step_after_first_contact_encodes_byte_for_byte()
    {
        var bytes = RemoteApiCodec.Encode(new RemoteApiRequest("sim.step", [], "u", null));
        byte[] expected =
        [
            0xA4,                                                       // map of 4 pairs
            0x64, (byte)'f', (byte)'u', (byte)'n', (byte)'c',           // "func"
            0x68, .. "sim.step"u8,                                      // text of 8
            0x64, (byte)'a', (byte)'r', (byte)'g', (byte)'s',           // "args"
            0x80,                                                       // empty array
            0x65, .. "argsL"u8, 0x00,                                   // "argsL": 0
            0x64, .. "uuid"u8, 0x61, (byte)'u',                         // "uuid": "u"
        ];
        Assert.Equal(expected, bytes);
    }

    [Fact]
    public void Get_object_with_no_error_on_first_contact_encodes_byte_for_byte()
    {
        var options = new Dictionary<string, object?> { ["noError"] = true };
        var bytes = RemoteApiCodec.Encode(new RemoteApiRequest("sim.getObject", ["/LB1", options], "ab", 5));
        byte[] expected =
        [
            0xA7,                                                       // map of 7 pairs
            0x64, .. "func"u8, 0x6D, .. "sim.getObject"u8,              // text of 13
            0x64, .. "args"u8, 0x82,                                    // array of 2
            0x64, .. "/LB1"u8,
            0xA1, 0x67, .. "noError"u8, 0xF5,                           // { "noError": true }
            0x65, .. "argsL"u8, 0x02,
            0x64, .. "uuid"u8, 0x62, .. "ab"u8,
            0x63, .. "ver"u8, 0x02,
            0x64, .. "lang"u8, 0x66, .. "csharp"u8,
            0x67, .. "timeout"u8, 0x05,
        ];
        Assert.Equal(expected, bytes);
    }

    [Fact]
    public void Set_joint_position_encodes_the_handle_as_integer_and_the_angle_as_float64()
    {
        var bytes = RemoteApiCodec.Encode(new RemoteApiRequest("sim.setJointPosition", [12L, 0.5], "u", null));
        byte[] expected =
        [
            0xA4,
            0x64, .. "func"u8, 0x74, .. "sim.setJointPosition"u8,       // text of 20
            0x64, .. "args"u8, 0x82,
            0x0C,                                                       // 12
            0xFB, 0x3F, 0xE0, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,       // 0.5 as IEEE 754 binary64
            0x65, .. "argsL"u8, 0x02,
            0x64, .. "uuid"u8, 0x61, (byte)'u',
        ];
        Assert.Equal(expected, bytes);
    }

    [Fact]
    public void Nil_travels_as_the_nil_word_and_decodes_back_to_null()
    {
        var bytes = RemoteApiCodec.Encode(new RemoteApiRequest("f", [null, -1L], "u", null));
        byte[] nil = [0x67, .. "_*NIL*_"u8, 0x20]; // the word, then -1 (major type 1, value 0)
        Assert.True(bytes.AsSpan().IndexOf(nil) > 0);
        var decoded = (IReadOnlyDictionary<string, object?>)RemoteApiCodec.Decode(bytes)!;
        Assert.Equal(new object?[] { null, -1L }, (IReadOnlyList<object?>)decoded["args"]!);
    }

    [Fact]
    public void Error_replies_have_newlines_and_tabs_restored()
    {
        byte[] reply = [0xA1, 0x63, .. "err"u8, 0x70, .. "a_=NL=_b_=TB=_c."u8];
        var decoded = RemoteApiCodec.DecodeReply(reply);
        Assert.Equal("a\nb\tc.", decoded.Error);
        Assert.Null(decoded.Func);
    }

    [Fact]
    public void Malformed_reply_is_a_format_error()
    {
        Assert.Throws<FormatException>(() => RemoteApiCodec.DecodeReply(new byte[] { 0xA1, 0x63 }));
        Assert.Throws<FormatException>(() => RemoteApiCodec.DecodeReply(new byte[] { 0x01 }));
    }
}
