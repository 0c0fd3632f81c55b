using System.Buffers.Binary;
using RobotControl.Bus.Transports;

namespace RobotControl.Host.Tests.Safety;

/// <summary>
/// The host's end of the virtual bus with an ear on it: every sync write to <c>goal_position</c> the virtual robot
/// receives is decoded (byte stuffing removed) into goal counts per module and channel, with its time on the bus clock.
/// </summary>
internal sealed class GoalFrameSpy(IByteLink inner, TimeProvider clock, ushort goalAddress, int stride) : IByteLink
{
    private const byte SyncWrite = 0x83;

    /// <summary>Every goal frame: bus time (s), module ID -> goal counts by channel.</summary>
    public List<(double TimeS, Dictionary<byte, int[]> Goals)> Frames { get; } = [];

    /// <summary>
    /// The largest goal step between consecutive frames (from frame <paramref name="first"/>, up to bus time
    /// <paramref name="untilS"/>) as a fraction of the step cap: the motor's maximum output speed times the time
    /// between the frames, plus one count of rounding. At most 1: no frame exceeded the cap.
    /// </summary>
    public double WorstStepOverCap(IEnumerable<(byte ModuleId, int Channel, double CountsPerRad, double SpeedLimitRadS)> motors, int first = 0, double untilS = double.PositiveInfinity)
    {
        var list = motors.ToList();
        var worst = 0.0;
        for (var k = Math.Max(first, 0) + 1; k < Frames.Count && Frames[k].TimeS <= untilS; k++)
        {
            var (t0, g0) = Frames[k - 1];
            var (t1, g1) = Frames[k];
            foreach (var m in list)
            {
                if (g0.TryGetValue(m.ModuleId, out var a) && g1.TryGetValue(m.ModuleId, out var b))
                {
                    var stepRad = Math.Abs(b[m.Channel] - a[m.Channel]) / m.CountsPerRad;
                    worst = Math.Max(worst, stepRad / ((m.SpeedLimitRadS * (t1 - t0)) + (1 / m.CountsPerRad)));
                }
            }
        }

        return worst;
    }

    public string Description => inner.Description;

    public int BaudRate => inner.BaudRate;

    public void Write(ReadOnlySpan<byte> data)
    {
        Decode(data);
        inner.Write(data);
    }

    public int Read(Span<byte> buffer, TimeSpan timeout) => inner.Read(buffer, timeout);

    public void DiscardInput() => inner.DiscardInput();

    public void Dispose() => inner.Dispose();

    private void Decode(ReadOnlySpan<byte> frame)
    {
        if (frame.Length < 14 || frame[0] != 0xFF || frame[1] != 0xFF || frame[2] != 0xFD || frame[7] != SyncWrite)
        {
            return;
        }

        // Instruction and parameters without the stuffing byte the protocol puts after every FF FF FD.
        var body = new List<byte>();
        var pattern = false;
        for (var i = 7; i < frame.Length - 2; i++)
        {
            if (pattern && frame[i] == 0xFD)
            {
                pattern = false;
                continue;
            }

            body.Add(frame[i]);
            pattern = body.Count >= 3 && body[^1] == 0xFD && body[^2] == 0xFF && body[^3] == 0xFF;
        }

        body.RemoveAt(0); // the instruction
        var p = body.ToArray();
        if (BinaryPrimitives.ReadUInt16LittleEndian(p) != goalAddress)
        {
            return;
        }

        var length = BinaryPrimitives.ReadUInt16LittleEndian(p.AsSpan(2));
        var goals = new Dictionary<byte, int[]>();
        for (var at = 4; at + 1 + length <= p.Length; at += 1 + length)
        {
            var counts = new int[length / stride];
            for (var ch = 0; ch < counts.Length; ch++)
            {
                counts[ch] = BinaryPrimitives.ReadInt32LittleEndian(p.AsSpan(at + 1 + (ch * stride)));
            }

            goals[p[at]] = counts;
        }

        Frames.Add((clock.GetTimestamp() / (double)clock.TimestampFrequency, goals));
    }
}
