using System.Buffers.Binary;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Transports;

namespace RobotControl.Modules.Tests;

/// <summary>
/// The host's end of a virtual bus with a tap on it: every WRITE instruction is recorded (module, address), and the
/// first byte of the value of a WRITE to <see cref="CorruptAddress"/> is changed on the wire with the CRC made to
/// match, so the module stores something else than the host sent and acknowledges it.
/// </summary>
internal sealed class TappedLink(IByteLink inner) : IByteLink, IClockedLink
{
    /// <summary>Each WRITE the host sent, in order.</summary>
    public List<(byte Id, ushort Address)> Writes { get; } = [];

    /// <summary>The address whose written value is changed on the wire, or null.</summary>
    public ushort? CorruptAddress { get; set; }

    public string Description => inner.Description;

    public int BaudRate => inner.BaudRate;

    public TimeProvider Clock => ((IClockedLink)inner).Clock;

    public void Write(ReadOnlySpan<byte> data)
    {
        // Header FF FF FD 00, ID, length (2), instruction, parameters, CRC (2); the values here need no byte stuffing.
        if (data[7] != (byte)Instruction.Write)
        {
            inner.Write(data);
            return;
        }

        var parameters = data[8..^2].ToArray();
        var address = BinaryPrimitives.ReadUInt16LittleEndian(parameters);
        Writes.Add((data[4], address));
        if (address != CorruptAddress)
        {
            inner.Write(data);
            return;
        }

        parameters[2]++;
        var frame = new byte[data.Length + 8];
        inner.Write(frame.AsSpan(0, FrameEncoder.EncodeInstruction(frame, data[4], Instruction.Write, parameters)));
    }

    public int Read(Span<byte> buffer, TimeSpan timeout) => inner.Read(buffer, timeout);

    public void DiscardInput() => inner.DiscardInput();

    public void Dispose() => inner.Dispose();
}
