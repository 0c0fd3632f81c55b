using System.Buffers.Binary;
using System.Diagnostics;
using RobotControl.Bench.EStop;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Transports;

namespace RobotControl.Bus.Tests.Bench;

/// <summary>
/// The E-STOP benchmark's frame detector (bench/RobotControl.Bench/EStop, compiled in here) on frames built by hand:
/// what it counts as a torque-off or a hold frame, and that its tap records only the first one after the request's
/// arrival. Correctness only: no timing is asserted.
/// </summary>
public sealed class EStopFrameDetectorTests
{
    private static readonly ushort TorqueAddress = ControlTable.Firmware["torque_enable"].At(0);
    private static readonly ushort GoalAddress = ControlTable.Firmware["goal_position"].At(0);

    [Fact]
    public void A_write_of_zeros_to_torque_enable_is_a_torque_off_frame_and_of_a_one_is_not()
    {
        var detector = new EStopFrameDetector();
        Assert.Equal(StopFrame.TorqueOff, detector.Classify(Write(3, TorqueAddress, [0, 0, 0])));
        Assert.Equal(StopFrame.Other, detector.Classify(Write(3, TorqueAddress, [0, 1, 0])));
        Assert.Equal(StopFrame.Other, detector.Classify(Write(3, (ushort)(TorqueAddress + 1), [0, 0, 0])));
    }

    [Fact]
    public void A_goal_sync_write_repeating_the_goals_before_it_is_a_hold_and_a_changed_one_is_not()
    {
        var detector = new EStopFrameDetector();
        Assert.Equal(StopFrame.Goals, detector.Classify(GoalSyncWrite(1000, -2000)));
        Assert.Equal(StopFrame.Goals, detector.Classify(GoalSyncWrite(1001, -2000)));
        Assert.Equal(StopFrame.Hold, detector.Classify(GoalSyncWrite(1001, -2000)));
        Assert.Equal(StopFrame.Hold, detector.Classify(GoalSyncWrite(1001, -2000)));
        Assert.Equal(StopFrame.Goals, detector.Classify(GoalSyncWrite(1001, -1999)));
    }

    [Fact]
    public void Goals_that_need_byte_stuffing_are_compared_unstuffed()
    {
        // 0xFDFFFF00 little-endian is FF FF FD 00 inside the parameters: the encoder stuffs it, the detector must not care.
        var detector = new EStopFrameDetector();
        var stuffed = GoalSyncWrite(unchecked((int)0x00FDFFFF), 5);
        Assert.Equal(StopFrame.Goals, detector.Classify(stuffed));
        Assert.Equal(StopFrame.Hold, detector.Classify(stuffed));
    }

    [Fact]
    public void Other_frames_are_neither_and_do_not_break_a_hold()
    {
        var detector = new EStopFrameDetector();
        Assert.Equal(StopFrame.Goals, detector.Classify(GoalSyncWrite(7, 8)));
        Assert.Equal(StopFrame.Other, detector.Classify(Frame(FrameConstants.BroadcastId, Instruction.SyncWrite, [(byte)(GoalAddress + 4), (byte)((GoalAddress + 4) >> 8), 4, 0, 1, 0, 0, 0, 0])));
        Assert.Equal(StopFrame.Other, detector.Classify(Frame(1, Instruction.Read, [(byte)TorqueAddress, (byte)(TorqueAddress >> 8), 1, 0])));
        Assert.Equal(StopFrame.Other, detector.Classify([0xFF, 0xFF, 0xFD]));
        Assert.Equal(StopFrame.Hold, detector.Classify(GoalSyncWrite(7, 8)));
    }

    [Fact]
    public void The_tap_records_the_first_wanted_frame_after_the_arrival_only()
    {
        using var tap = new EStopTapLink(new NullLink(), TimeProvider.System) { Wanted = StopFrame.TorqueOff };
        tap.Write(Write(1, TorqueAddress, [0]));
        Assert.False(tap.TryTake(out _, out _)); // not armed: a torque-off before the request is not the stop's

        var arrival = Stopwatch.GetTimestamp();
        tap.Arm(arrival);
        tap.Write(GoalSyncWrite(1, 2));
        tap.Write(GoalSyncWrite(1, 2)); // a hold, but not the wanted kind
        Assert.False(tap.TryTake(out _, out _));
        tap.Write(Write(1, TorqueAddress, [0]));
        Assert.True(tap.TryTake(out var first, out var kind));
        Assert.Equal(StopFrame.TorqueOff, kind);
        Assert.True(first >= arrival);
        Assert.Equal(arrival, tap.ArrivedAt);
        tap.Write(Write(2, TorqueAddress, [0]));
        Assert.True(tap.TryTake(out var still, out _));
        Assert.Equal(first, still); // the first frame stays until the next arrival
        Assert.Equal(2, tap.CycleStartsSince(arrival).Length); // the goal SYNC WRITEs since the arrival: the bus cycles
    }

    private static byte[] Write(byte id, ushort address, byte[] data)
    {
        var p = new byte[2 + data.Length];
        BinaryPrimitives.WriteUInt16LittleEndian(p, address);
        data.CopyTo(p, 2);
        return Frame(id, Instruction.Write, p);
    }

    /// <summary>A goal SYNC WRITE to modules 1 and 2, one 4-byte goal each.</summary>
    private static byte[] GoalSyncWrite(int goal1, int goal2)
    {
        var p = new byte[4 + (2 * 5)];
        BinaryPrimitives.WriteUInt16LittleEndian(p, GoalAddress);
        BinaryPrimitives.WriteUInt16LittleEndian(p.AsSpan(2), 4);
        p[4] = 1;
        BinaryPrimitives.WriteInt32LittleEndian(p.AsSpan(5), goal1);
        p[9] = 2;
        BinaryPrimitives.WriteInt32LittleEndian(p.AsSpan(10), goal2);
        return Frame(FrameConstants.BroadcastId, Instruction.SyncWrite, p);
    }

    private static byte[] Frame(byte id, Instruction instruction, byte[] parameters)
    {
        var buffer = new byte[FrameConstants.MaxFrameSize];
        return buffer[..FrameEncoder.EncodeInstruction(buffer, id, instruction, parameters)];
    }

    private sealed class NullLink : IByteLink
    {
        public string Description => "null";

        public int BaudRate => 1_000_000;

        public void Write(ReadOnlySpan<byte> data)
        {
        }

        public int Read(Span<byte> buffer, TimeSpan timeout) => 0;

        public void DiscardInput()
        {
        }

        public void Dispose()
        {
        }
    }
}
