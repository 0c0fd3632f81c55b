using System.Buffers.Binary;
using RobotControl.Bus.Protocol;
using RobotControl.Robot.Control;
using RobotControl.Robot.Events;
using RobotControl.Simulation;
using RobotControl.Simulation.Bus;
using RobotControl.TestSupport;

namespace RobotControl.Robot.Tests.Bus;

public sealed class FaultTests
{
    private const double Deg = Math.PI / 180;

    [Fact]
    public void Corrupted_frames_are_never_acted_on()
    {
        using var lb = new VirtualLb();
        var target = new[] { -10 * Deg, 5 * Deg, 20 * Deg, 60 * Deg, 30 * Deg };
        lb.Robot.WriteJointSetpoints(0, target);
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(20));
        var goal = ControlTable.Firmware["goal_position"];
        var expected = lb.Sim.Axes.ToDictionary(a => a, a => lb.Robot.Motor(a.Config.FullName).Config.ToCounts(Goal(lb, a, target)));

        // One bit in 2000 flipped: most cycles lose a frame somewhere, thousands of frames are corrupted.
        lb.Sim.WireFaults = new WireFaults { BitErrorRate = 5e-4, ByteDropRate = 1e-4 };
        Span<byte> four = stackalloc byte[4];
        for (var i = 0; i < 400; i++)
        {
            lb.Robot.RunCycle();
            foreach (var axis in lb.Sim.Axes)
            {
                lb.Sim.PeekTable(axis.Config.ModuleId, goal.At(axis.Config.Channel), four);
                Assert.Equal(expected[axis], BinaryPrimitives.ReadInt32LittleEndian(four));
            }
        }

        Assert.True(lb.Sim.CorruptedBytes > 100, $"only {lb.Sim.CorruptedBytes} bytes corrupted");
        Assert.True(lb.Robot.Client.CrcErrors > 10, $"only {lb.Robot.Client.CrcErrors} CRC errors seen by the host");
        Assert.True(lb.Robot.Client.Statistics(1).Retries > 0);
    }

    [Fact]
    public void A_module_reset_by_EMI_resumes_its_position_from_FRAM_and_is_reported()
    {
        using var lb = new VirtualLb();
        var target = new[] { 0.0, 0.0, 0.0, 80 * Deg, 60 * Deg };
        lb.Robot.WriteJointSetpoints(0, target);
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(1200));
        var elbow = lb.Sim.Axis(0, "elbow");
        var before = elbow.OutputAngleRad;

        lb.Sim.ScheduleReset(2, lb.Sim.Elapsed + TimeSpan.FromMilliseconds(10));
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(300));

        Assert.True(lb.Robot.Faults.HasFlag(RobotFaults.ModuleReset));
        Assert.Equal(1, lb.Robot.Controller(2)!.Resets);
        var reset = Assert.Single(lb.Robot.Events.History().OfType<ModuleResetEvent>());
        Assert.Equal((byte)2, reset.ModuleId);
        Assert.Equal("brown-out", reset.Cause);
        Assert.True(reset.ResumedFromFram);
        Assert.Contains("resumed its position from FRAM", reset.Message, StringComparison.Ordinal);
        Assert.True(elbow.DriverEnabled, "the host re-armed the module");
        Assert.InRange(lb.Robot.Motor("right.elbow").PositionRad - elbow.OutputAngleRad, -1 * Deg, 1 * Deg); // within the backlash
        Assert.InRange(elbow.OutputAngleRad - before, -1 * Deg, 1 * Deg);

        // It still follows setpoints.
        lb.Robot.WriteJointSetpoints(0, [0.0, 0.0, 0.0, 100 * Deg, 60 * Deg]);
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(800));
        Assert.InRange(lb.Robot.Motor("right.elbow").PositionRad - (100 * Deg), -0.5 * Deg, 0.5 * Deg);
    }

    [Fact]
    public void The_watchdog_stops_the_motors_when_the_host_falls_silent_past_its_second_stage()
    {
        using var lb = new VirtualLb();
        lb.Robot.WriteJointSetpoints(0, [-40 * Deg, 0, 0, 120 * Deg, 0]);
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(100));
        Assert.All(lb.Sim.Axes, a => Assert.True(a.DriverEnabled));

        lb.Sim.Advance(TimeSpan.FromMilliseconds(lb.Definition.Modules.WatchdogOffMs - 20)); // the host sends nothing
        Assert.All(lb.Sim.Axes, a => Assert.True(a.DriverEnabled)); // holding (stage 1), not off
        lb.Sim.Advance(TimeSpan.FromMilliseconds(40));
        Assert.All(lb.Sim.Axes, a => Assert.False(a.DriverEnabled));
        lb.Sim.Advance(TimeSpan.FromMilliseconds(100)); // coasting ends
        var elbow = lb.Sim.Axis(0, "elbow").OutputAngleRad;
        lb.Sim.Advance(TimeSpan.FromMilliseconds(300));
        Assert.InRange(lb.Sim.Axis(0, "elbow").OutputAngleRad - elbow, -0.1 * Deg, 0.1 * Deg); // stopped,
        Assert.True(120 * Deg - elbow > 10 * Deg, "the elbow stopped short of its goal"); // not creeping to the goal

        lb.Robot.RunFor(TimeSpan.FromMilliseconds(30));
        Assert.True(lb.Robot.Faults.HasFlag(RobotFaults.WatchdogTripped));
        Assert.All(lb.Sim.Axes, a => Assert.False(a.DriverEnabled));

        lb.Robot.ClearFaults();
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(30));
        Assert.False(lb.Robot.Faults.HasFlag(RobotFaults.WatchdogTripped));
        Assert.All(lb.Sim.Axes, a => Assert.True(a.DriverEnabled));
    }

    [Fact]
    public void A_stalled_motor_runs_into_its_current_limit()
    {
        using var lb = new VirtualLb();
        var elbow = lb.Sim.Axis(0, "elbow");
        var start = elbow.OutputAngleRad;
        elbow.ObstacleTorqueNm = 5; // far beyond what the elbow drive can push
        lb.Robot.WriteJointSetpoints(0, [lb.Definition.Joints[0].MidRad, lb.Definition.Joints[1].MidRad, lb.Definition.Joints[2].MidRad, start + (30 * Deg), 0]);
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(600));

        var motor = lb.Robot.Motor("right.elbow");
        Assert.InRange(elbow.OutputAngleRad - start, -1 * Deg, 1 * Deg);
        Assert.InRange(motor.CurrentA, 0.8 * motor.CurrentLimitA, 1.2 * motor.CurrentLimitA);
        Assert.InRange(Math.Abs(elbow.CurrentA), 0.7 * motor.CurrentLimitA, 1.3 * motor.CurrentLimitA);
        Assert.True(lb.Robot.Faults.HasFlag(RobotFaults.CurrentLimited));
    }

    [Fact]
    public void A_bus_cycle_allocates_nothing()
    {
        using var lb = new VirtualLb();
        lb.Robot.WriteJointSetpoints(0, [-10 * Deg, 5 * Deg, 20 * Deg, 60 * Deg, 30 * Deg]);
        for (var i = 0; i < 20; i++)
        {
            lb.Robot.RunCycle();
        }

        var before = GC.GetAllocatedBytesForCurrentThread();
        for (var i = 0; i < 100; i++)
        {
            lb.Robot.RunCycle();
        }

        Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
    }

    private static double Goal(VirtualLb lb, VirtualAxis axis, double[] target)
    {
        if (axis.Config.Arm != 0)
        {
            return lb.Robot.Motor(axis.Config.FullName).PositionRad;
        }

        if (!axis.Config.Actuator.IsKinematic)
        {
            return lb.Robot.Motor(axis.Config.FullName).PositionRad;
        }

        var k = lb.Robot.Map.IndexOfActuator(axis.Config.Actuator.Name);
        return Enumerable.Range(0, 5).Sum(j => lb.Robot.Map.Coefficient(k, j) * target[j]);
    }
}
