using RobotControl.Bus.Protocol;

namespace RobotControl.Bench.EStop;

/// <summary>What a frame the host writes is, for the E-STOP benchmark.</summary>
internal enum StopFrame
{
    /// <summary>Anything else.</summary>
    Other,

    /// <summary>A goal SYNC WRITE whose goals differ from the goal SYNC WRITE before it.</summary>
    Goals,

    /// <summary>A goal SYNC WRITE that repeats the goals of the one before it, byte for byte: the goals are frozen (a hold).</summary>
    Hold,

    /// <summary>A WRITE of zeros to <c>torque_enable</c>: a module's motors off.</summary>
    TorqueOff,
}

/// <summary>
/// Classifies the frames the host writes to the bus (Dynamixel 2.0, byte stuffing removed by <see cref="FrameDecoder"/>)
/// into the frames an emergency stop sends: the motors off (a WRITE of zeros to <c>torque_enable</c>) or a hold (a
/// goal SYNC WRITE whose goals repeat those of the goal SYNC WRITE before it). Addresses come from
/// <see cref="ControlTable.Firmware"/>. Used on the bus thread only; not thread-safe.
/// </summary>
internal sealed class EStopFrameDetector
{
    private static readonly ushort TorqueAddress = ControlTable.Firmware["torque_enable"].At(0);
    private static readonly ushort GoalAddress = ControlTable.Firmware["goal_position"].At(0);
    private readonly FrameDecoder _decoder = new();
    private readonly byte[] _lastGoals = new byte[FrameConstants.MaxFrameSize];
    private int _lastGoalsLength = -1;

    /// <summary>
    /// The kind of the frames in <paramref name="written"/> (one Write call of the host: normally one frame); of
    /// several, the one that matters most for a stop (torque off, then hold, then goals).
    /// </summary>
    public StopFrame Classify(ReadOnlySpan<byte> written)
    {
        var kind = StopFrame.Other;
        var rest = written;
        while (_decoder.Push(rest, out var used))
        {
            rest = rest[used..];
            var frame = ClassifyFrame(_decoder.Instruction, _decoder.Parameters);
            kind = (StopFrame)Math.Max((int)kind, (int)frame);
        }

        _decoder.Reset(); // the host writes whole frames: nothing is carried over to the next Write
        return kind;
    }

    private StopFrame ClassifyFrame(byte instruction, ReadOnlySpan<byte> parameters)
    {
        if (parameters.Length < 3)
        {
            return StopFrame.Other;
        }

        var address = (ushort)(parameters[0] | (parameters[1] << 8));
        if (instruction == (byte)Instruction.Write && address == TorqueAddress)
        {
            return parameters[2..].ContainsAnyExcept((byte)0) ? StopFrame.Other : StopFrame.TorqueOff;
        }

        if (instruction != (byte)Instruction.SyncWrite || address != GoalAddress)
        {
            return StopFrame.Other;
        }

        var goals = parameters[4..]; // after address and length: ID, data; ID, data; ...
        var same = goals.SequenceEqual(_lastGoals.AsSpan(0, Math.Max(0, _lastGoalsLength)));
        goals.CopyTo(_lastGoals);
        _lastGoalsLength = goals.Length;
        return same ? StopFrame.Hold : StopFrame.Goals;
    }
}
