using System.Buffers.Binary;
using RobotControl.Bus.Client;

namespace RobotControl.Robot.Bus;

/// <summary>
/// The pot poll: every <see cref="BusRobotOptions.PotPollCycles"/> cycles (half-way between status polls) one sync
/// read of every module's <c>pot_raw</c>, turned into each motor's <see cref="RobotMotor.PotPositionRad"/> through the
/// calibration the robot file gives it (what the modules hold). Allocation-free.
/// </summary>
public sealed partial class BusRobot
{
    private byte[] _potData = [];
    private Reply[] _potReplies = [];

    private bool IsPotPollCycle(long cycle) =>
        _options.PotPollCycles > 0 && cycle % _options.PotPollCycles == _options.PotPollCycles / 2;

    private void PollPots()
    {
        if (_ids.Length == 0)
        {
            return;
        }

        _client.SyncRead(_potAddress, _potLength, _ids, _potData, _potReplies);
        for (var i = 0; i < _active.Length; i++)
        {
            if (_potReplies[i].Outcome != ReplyOutcome.Ok)
            {
                continue;
            }

            foreach (var m in _active[i].MotorArray)
            {
                var raw = BinaryPrimitives.ReadUInt16LittleEndian(_potData.AsSpan((i * _potLength) + (m.Config.Channel * _potStride)));
                m.PublishPot(raw);
            }
        }
    }

    private void ResizePotBuffers()
    {
        _potData = new byte[_ids.Length * _potLength];
        _potReplies = new Reply[_ids.Length];
    }
}
