using System.Text.Json;
using RobotControl.Bus.Protocol;
using RobotControl.TestSupport;

namespace RobotControl.Bus.Tests.Protocol;

/// <summary>The C# codec against the firmware's shared test vectors (firmware/protocol/test-vectors.json).</summary>
public sealed class FirmwareVectorTests
{
    public static TheoryData<string> VectorNames()
    {
        var data = new TheoryData<string>();
        foreach (var v in Load())
        {
            data.Add(v.GetProperty("name").GetString()!);
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(VectorNames))]
    public void Codec_agrees_with_the_firmware_vector(string name)
    {
        var v = Load().Single(x => x.GetProperty("name").GetString() == name);
        var bytes = FrameCodecTests.Hex(v.GetProperty("hex").GetString()!);
        var decoder = new FrameDecoder();
        var delivered = decoder.Push(bytes, out _);
        if (!v.GetProperty("valid").GetBoolean())
        {
            Assert.False(delivered, $"{name} must be rejected: {v.GetProperty("reason").GetString()}");
            return;
        }

        Assert.True(delivered);
        var parameters = FrameCodecTests.Hex(v.GetProperty("params_hex").GetString()!);
        Assert.Equal(v.GetProperty("id").GetInt32(), decoder.Id);
        Assert.Equal(v.GetProperty("instruction").GetInt32(), decoder.Instruction);
        Assert.Equal(parameters, decoder.Parameters.ToArray());

        // Encoding the meaning gives back the exact wire bytes (stuffing and CRC included).
        var buffer = new byte[FrameConstants.MaxFrameSize];
        var n = v.GetProperty("kind").GetString() == "status"
            ? FrameEncoder.EncodeStatus(buffer, decoder.Id, (byte)v.GetProperty("error").GetInt32(), parameters)
            : FrameEncoder.EncodeInstruction(buffer, decoder.Id, (Instruction)decoder.Instruction, parameters);
        Assert.Equal(bytes, buffer[..n]);
        if (v.GetProperty("kind").GetString() == "status")
        {
            Assert.Equal(v.GetProperty("error").GetInt32(), decoder.Error);
        }
    }

    [Fact]
    public void The_embedded_control_table_is_the_firmware_file()
    {
        var file = ControlTable.Parse(File.ReadAllText(RepositoryPaths.Firmware("protocol/control-table.json")));
        var embedded = ControlTable.Firmware;
        Assert.Equal(file.Fields, embedded.Fields);
        Assert.Equal(0, embedded["model_number"].Address);
        Assert.Equal(7, embedded["id"].Address);
    }

    private static JsonElement[] Load()
    {
        using var doc = JsonDocument.Parse(File.ReadAllText(RepositoryPaths.Firmware("protocol/test-vectors.json")));
        return doc.RootElement.GetProperty("vectors").EnumerateArray().Select(e => e.Clone()).ToArray();
    }
}
