using RobotControl.Bus.Client;
using RobotControl.TestSupport;

namespace RobotControl.Robot.Tests.Bus;

/// <summary>
/// The one slot for work between cycles: an emergency stop cuts the running piece short at its next transaction, and
/// the next piece starts only after the write that takes the stop.
/// </summary>
public sealed class BetweenCyclesTests
{
    [Fact]
    public async Task An_emergency_hold_cuts_a_long_piece_of_work_short_at_its_next_transaction()
    {
        using var lb = new VirtualLb();
        var robot = lb.Robot;
        robot.Start();
        try
        {
            var reads = 0;
            var started = new TaskCompletionSource();
            var longWork = robot.Slot.Post("a long read", () =>
            {
                started.SetResult();
                for (var i = 0; i < 100_000; i++)
                {
                    robot.ReadParameter(1, "present_position");
                    reads++;
                }

                return reads;
            });
            var queued = robot.Slot.Post("queued behind it", () => robot.Cycles);
            await started.Task;
            var cyclesAtStop = robot.Cycles;

            robot.EmergencyHold("test stop", torqueOff: false);

            var cut = await Assert.ThrowsAsync<BusWorkInterruptedException>(() => longWork);
            Assert.Contains("test stop", cut.Message, StringComparison.Ordinal);
            Assert.InRange(reads, 0, 99_999);
            Assert.True(await queued > cyclesAtStop, "the queued piece ran before the write that took the stop");
            Assert.True(robot.IsHolding);
        }
        finally
        {
            robot.Stop();
        }
    }
}
