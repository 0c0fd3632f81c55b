using System.Buffers.Binary;
using RobotControl.Bus.Protocol;

namespace RobotControl.Bus.Client;

/// <summary>
/// Maintenance requests. REG WRITE and ACTION: a write each module checks and acknowledges now and applies later, all
/// of them at the same moment when the ACTION is broadcast (e.g. a baud change, where no module may move before the
/// others have agreed). The span of a complete broadcast ping (a scan for modules of any ID).
/// </summary>
public sealed partial class BusClient
{
    /// <summary>Byte times between the broadcast-ping replies of consecutive IDs (docs/protocol.md, "Timing").</summary>
    public const int PingSlotBytes = 16;

    /// <summary>Longest return delay a module can be set to (<c>return_delay_time</c> at its maximum, in units of 2 us).</summary>
    private static readonly TimeSpan MaxReturnDelay = TimeSpan.FromMicroseconds(ControlTable.Firmware["return_delay_time"].Max * 2);

    /// <summary>How long every ID 0..252 needs to answer a broadcast ping at <paramref name="baud"/>, whatever its return delay.</summary>
    public static TimeSpan BroadcastPingSpan(int baud)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(baud, 1);
        return TimeSpan.FromTicks((MaxId + 1L) * PingSlotBytes * 10 * TimeSpan.TicksPerSecond / baud) + MaxReturnDelay;
    }

    /// <summary>
    /// Registers <paramref name="data"/> at <paramref name="address"/> in module <paramref name="id"/>: checked as a write
    /// and acknowledged now, applied by the next ACTION (a new REG WRITE replaces it).
    /// </summary>
    public Reply RegWrite(byte id, ushort address, ReadOnlySpan<byte> data) => WriteAt(Instruction.RegWrite, id, address, data, _options.Retries);

    /// <summary>Makes module <paramref name="id"/> apply its registered write; the reply carries the write's status.</summary>
    public Reply Action(byte id) => Transact(id, Instruction.Action, ReadOnlySpan<byte>.Empty, 0);

    /// <summary>
    /// Broadcasts ACTION: every module applies its registered write at once; nobody replies. Returns when the frame has
    /// had its wire time and the reply margin, so every module has acted before the caller changes the line (e.g. its
    /// baud).
    /// </summary>
    public void ActionAll()
    {
        var sentAt = Send(FrameConstants.BroadcastId, Instruction.Action, ReadOnlySpan<byte>.Empty);
        var deadline = sentAt + Ticks(WireTime(FrameConstants.Overhead) + _options.ResponseMargin);
        while (NextFrame(deadline))
        {
            _strayFrames++; // nothing answers a broadcast ACTION
        }
    }

    /// <summary>WRITE or REG WRITE: the address, then the data; waits for the acknowledgement.</summary>
    private Reply WriteAt(Instruction instruction, byte id, ushort address, ReadOnlySpan<byte> data, int retries)
    {
        var p = _params.AsSpan(0, 2 + data.Length);
        BinaryPrimitives.WriteUInt16LittleEndian(p, address);
        data.CopyTo(p[2..]);
        return Transact(id, instruction, p, 0, retries);
    }
}
