using System.Buffers.Binary;

namespace RobotControl.Bus.Protocol;

/// <summary>
/// Writes Dynamixel 2.0 frames: header FF FF FD 00, ID, little-endian length, instruction, (error,) parameters with
/// FF FF FD stuffed to FF FF FD FD, CRC-16 over everything before it. Allocation-free.
/// </summary>
public static class FrameEncoder
{
    /// <summary>Encodes an instruction packet into <paramref name="destination"/>; returns its length.</summary>
    /// <exception cref="ArgumentException">The destination is too small for the stuffed frame.</exception>
    public static int EncodeInstruction(Span<byte> destination, byte id, Instruction instruction, ReadOnlySpan<byte> parameters) =>
        Encode(destination, id, (byte)instruction, hasError: false, 0, parameters);

    /// <summary>Encodes a status packet (instruction 0x55, error byte, parameters); returns its length.</summary>
    /// <exception cref="ArgumentException">The destination is too small for the stuffed frame.</exception>
    public static int EncodeStatus(Span<byte> destination, byte id, byte error, ReadOnlySpan<byte> parameters) =>
        Encode(destination, id, (byte)Instruction.Status, hasError: true, error, parameters);

    private static int Encode(Span<byte> dest, byte id, byte instruction, bool hasError, byte error, ReadOnlySpan<byte> parameters)
    {
        if (dest.Length < FrameConstants.Overhead + parameters.Length + (hasError ? 1 : 0))
        {
            throw new ArgumentException("destination too small for the frame", nameof(dest));
        }

        dest[0] = 0xFF;
        dest[1] = 0xFF;
        dest[2] = 0xFD;
        dest[3] = 0x00;
        dest[4] = id;
        var n = 7;
        var run = 0; // how many of the last region bytes form a prefix of FF FF FD
        n = Put(dest, n, instruction, ref run);
        if (hasError)
        {
            n = Put(dest, n, error, ref run);
        }

        foreach (var b in parameters)
        {
            n = Put(dest, n, b, ref run);
        }

        if (n + 2 > dest.Length)
        {
            throw new ArgumentException("destination too small for the stuffed frame", nameof(dest));
        }

        BinaryPrimitives.WriteUInt16LittleEndian(dest.Slice(5, 2), (ushort)(n + 2 - 7));
        var crc = Crc16.Compute(dest[..n]);
        BinaryPrimitives.WriteUInt16LittleEndian(dest.Slice(n, 2), crc);
        return n + 2;
    }

    private static int Put(Span<byte> dest, int n, byte b, ref int run)
    {
        if ((uint)n >= (uint)dest.Length - 2)
        {
            throw new ArgumentException("destination too small for the stuffed frame", nameof(dest));
        }

        dest[n++] = b;
        run = StuffState.Next(run, b);
        if (run == 3)
        {
            dest[n++] = 0xFD;
            run = 0;
        }

        return n;
    }
}

/// <summary>Tracks how much of the FF FF FD pattern the last bytes of a frame's payload form.</summary>
internal static class StuffState
{
    public static int Next(int run, byte b) => b switch
    {
        0xFF => run >= 2 ? 2 : run + 1,
        0xFD when run == 2 => 3,
        _ => 0,
    };
}
