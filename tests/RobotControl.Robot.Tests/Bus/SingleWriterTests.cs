using System.Diagnostics;
using System.Reflection;
using RobotControl.Robot.Bus;
using RobotControl.Robot.States;
using RobotControl.TestSupport;

namespace RobotControl.Robot.Tests.Bus;

/// <summary>
/// Every field of the robot core has one writing thread: the setpoints the loop's, everything else the bus thread's.
/// Set-up called from another thread while the bus thread runs is queued for it and waited for; it never writes the
/// setpoints (turning the motors on seeds the goals instead), so a sequence lock never sees two writers.
/// </summary>
public sealed class SingleWriterTests
{
    private const int Calls = 10_000;

    [Fact]
    [Trait("Category", "Stress")] // about a minute: left out of mutation runs (tools/mutation/Robot.json), never out of the test command
    public async Task Torque_on_off_and_homing_from_another_thread_while_the_loop_and_bus_run_never_hang_and_never_tear_a_setpoint()
    {
        using var lb = new VirtualLb();
        var robot = lb.Robot;
        var mid = robot.Definition.Joints.Select(j => j.MidRad).ToArray();
        var torn = 0L;
        var reads = 0L;
        robot.Setpoints.Observer = (arm, q) =>
        {
            // The loop writes every joint of a vector with the same offset from mid-range (+d or -d): a vector mixing
            // the two, or any other value once the loop has written, is a torn read.
            if (Volatile.Read(ref reads) >= 0 && q[0] != 0)
            {
                var sign = Math.Sign(q[0] - mid[0]);
                for (var j = 0; j < q.Length; j++)
                {
                    if (Math.Abs(q[j] - mid[j] - (sign * Offset)) > 1e-12)
                    {
                        Interlocked.Increment(ref torn);
                    }
                }
            }

            Interlocked.Increment(ref reads);
        };

        using var stop = new CancellationTokenSource();
        var loop = new Thread(() => WriteAtRate(robot, mid, stop.Token)) { Name = "test loop", IsBackground = true };
        loop.Start();
        SpinWait.SpinUntil(() => robot.Setpoints.JointVersion(0) > 0);
        robot.Start();
        var calls = 0;
        var setup = Task.Run(() =>
        {
            for (var i = 0; calls < Calls; i++)
            {
                robot.EnableTorque(false);
                calls++;
                if (i % 20 == 0)
                {
                    Assert.All(robot.Home(), r => Assert.True(r.Succeeded, r.ToString()));
                    calls++;
                }

                robot.EnableTorque(true);
                calls++;
            }
        });

        var finished = await Task.WhenAny(setup, Task.Delay(TimeSpan.FromMinutes(3))) == setup;
        stop.Cancel();
        robot.Stop();
        loop.Join();

        Assert.True(finished, $"set-up from another thread hung after {calls} of {Calls} calls (the bus thread stuck in a setpoint read?)");
        await setup; // its assertions
        Assert.True(Interlocked.Read(ref reads) > Calls, $"the bus thread read the setpoints only {reads} times");
        Assert.Equal(0, Interlocked.Read(ref torn));
        Assert.Equal(RobotState.Enabled, robot.State);
    }

    [Fact]
    public async Task Set_up_called_from_another_thread_runs_on_the_bus_thread_between_cycles()
    {
        using var lb = new VirtualLb();
        var robot = lb.Robot;
        robot.Start();
        try
        {
            var before = robot.Slot.Ran;
            var busThread = await robot.Slot.Post("which thread", () => Environment.CurrentManagedThreadId);
            robot.EnableTorque(false);

            Assert.NotEqual(Environment.CurrentManagedThreadId, busThread);
            Assert.Equal(before + 2, robot.Slot.Ran); // both ran as pieces of work between cycles
            Assert.Equal(RobotState.Discovered, robot.State);

            // Every set-up call of the robot does so (each names its piece of work).
            Assert.True(robot.Discover().AllAsConfigured);
            Assert.Empty(robot.CheckParameters());
            var kp = robot.ReadParameter(2, "kp", 0);
            Assert.Equal(kp, robot.WriteParameter(2, "kp", 0, kp));
            Assert.True(robot.WriteParameters() > 0);
            Assert.All(robot.Home(), r => Assert.True(r.Succeeded, r.ToString()));
            Assert.True(robot.HomeMotor(robot.Motor("right.elbow")).Succeeded);
            Assert.True(robot.Reboot(3).Succeeded);
            robot.EnableTorque(true);
            robot.EnableTorque(false);
            Assert.Equal(before + 12, robot.Slot.Ran);
            Assert.Equal(RobotState.Homed, robot.State);
        }
        finally
        {
            robot.Stop();
        }
    }

    [Fact]
    public void Every_part_of_the_robot_core_says_which_thread_writes_it()
    {
        var parts = typeof(BusRobot).Assembly.GetTypes()
            .Where(t => t.Namespace == typeof(BusRobot).Namespace && t.IsClass && !t.IsAbstract && !t.IsNested && !typeof(Delegate).IsAssignableFrom(t)
                && !typeof(Attribute).IsAssignableFrom(t) && !typeof(Exception).IsAssignableFrom(t)
                && t.GetFields(BindingFlags.Instance | BindingFlags.NonPublic | BindingFlags.Public).Any(f => !f.IsInitOnly && !f.Name.Contains("BackingField", StringComparison.Ordinal)))
            .ToList();

        Assert.Contains(typeof(BusRobot).Assembly.GetType("RobotControl.Robot.Bus.GoalWriter"), parts);
        var unmarked = parts.Where(t => t.GetCustomAttribute<WrittenByAttribute>() is null && t != typeof(BusRobot)).Select(t => t.Name).ToList();
        Assert.True(unmarked.Count == 0, $"mutable parts of the robot core that do not say which thread writes them: {string.Join(", ", unmarked)}");
        Assert.Equal(RobotThread.Loop, typeof(BusRobot).Assembly.GetType("RobotControl.Robot.Bus.SetpointExchange")!.GetCustomAttribute<WrittenByAttribute>()!.Thread);
    }

    private const double Offset = 0.05;

    /// <summary>The loop's thread: vectors alternating between mid-range + d and mid-range - d on every joint, about every 50 us.</summary>
    private static void WriteAtRate(BusRobot robot, double[] mid, CancellationToken stop)
    {
        var q = new double[mid.Length];
        var sign = 1;
        var clock = Stopwatch.StartNew();
        while (!stop.IsCancellationRequested)
        {
            for (var j = 0; j < q.Length; j++)
            {
                q[j] = mid[j] + (sign * Offset);
            }

            for (var arm = 0; arm < robot.ArmCount; arm++)
            {
                robot.WriteJointSetpoints(arm, q);
            }

            sign = -sign;
            var next = clock.Elapsed + TimeSpan.FromMicroseconds(50);
            while (clock.Elapsed < next)
            {
                Thread.SpinWait(20);
            }
        }
    }
}
