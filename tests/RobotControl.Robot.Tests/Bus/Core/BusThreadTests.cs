using System.Runtime;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Events;

namespace RobotControl.Robot.Tests.Bus.Core;

/// <summary>
/// The bus thread of a wall-clock session: it owns the bus before <see cref="BusRobot.Start(Action)"/> returns, runs
/// its prologue first, waits out the minimum cycle period on the bus clock, reports a failing link once and then once
/// a second of bus time with how many failures it left out, and counts what the JIT compiled on it after its first cycle.
/// </summary>
public sealed class BusThreadTests
{
    [Fact]
    public async Task The_thread_runs_its_prologue_then_owns_the_bus_before_Start_returns()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        Assert.Throws<ArgumentNullException>(() => robot.Start(null!));
        Assert.False(robot.IsRunning);

        var prologue = new List<(string? Name, long Cycles)>();
        robot.Start(() =>
        {
            prologue.Add((Thread.CurrentThread.Name, robot.Cycles));
            Thread.Sleep(50); // a slow prologue: Start still returns only once the thread owns the bus
        });
        try
        {
            Assert.True(robot.IsRunning);
            var bus = robot.Slot.Run("which thread", () => (Thread.CurrentThread.Name, Thread.CurrentThread.IsBackground, Thread.CurrentThread.Priority, Environment.CurrentManagedThreadId));
            Assert.Equal(($"bus {robot.Definition.Name}", true, ThreadPriority.AboveNormal), (bus.Name, bus.IsBackground, bus.Priority));
            Assert.NotEqual(Environment.CurrentManagedThreadId, bus.CurrentManagedThreadId);

            robot.Start(() => prologue.Add(("second", -1))); // already running: nothing happens
            Assert.Equal(bus.CurrentManagedThreadId, await robot.Slot.Post("again", () => Environment.CurrentManagedThreadId));
            Assert.Equal([($"bus {robot.Definition.Name}", 0L)], prologue);
        }
        finally
        {
            robot.Stop();
        }

        Assert.False(robot.IsRunning);
    }

    [Fact]
    public void The_thread_waits_out_the_minimum_cycle_period_on_the_bus_clock_and_stop_ends_the_wait()
    {
        // The bus clock reads days already (as a real clock's timestamps do), and moves only with bus traffic: with a
        // period of an hour, one cycle, then a wait.
        using var rig = new TappedLb(options: new BusRobotOptions { MinimumCyclePeriod = TimeSpan.FromHours(1) }, clockAt: TimeSpan.FromDays(3));
        var robot = rig.Robot;
        var tap = rig.Tap;
        var clock = rig.Clock;
        tap.FailureTime = TimeSpan.FromHours(2);
        robot.Start();
        try
        {
            Until(() => robot.Cycles >= 1, "the first cycle");
            Thread.Sleep(200); // dozens of cycles' worth of wall time
            Assert.Equal(1, robot.Cycles);

            // The hour passes (the bus clock moved by a failing cycle's two hours): no wait after a cycle that long.
            tap.Failing = true;
            clock.Advance(TimeSpan.FromHours(1));
            Until(() => tap.FailedWrites >= 5, "failed cycles back to back");
        }
        finally
        {
            robot.Stop();
        }

        Assert.False(robot.IsRunning);
    }

    [Fact]
    public void A_failing_link_is_reported_at_once_then_once_a_second_of_bus_time_with_the_failures_left_out()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        robot.Start();
        try
        {
            Until(() => robot.Cycles > 5, "cycles before the failure");
            rig.Tap.Failing = true; // each failure moves the bus clock 10 ms
            Until(() => rig.Tap.FailedWrites > 101, "a second of failures");
        }
        finally
        {
            robot.Stop();
        }

        var errors = rig.Events<BusError>().Select(e => e.Message).ToList();
        Assert.Equal("bus error: the test unplugged the adapter", errors[0]);
        Assert.Equal("bus error: the test unplugged the adapter (99 more failed cycles since the last report)", errors[1]); // the 101st failure, 1 s after the first
        Assert.True(rig.Checks >= rig.Tap.FailedWrites, "the check runs after a failed cycle too");
    }

    [Fact]
    public async Task The_thread_counts_the_methods_it_compiled_after_its_first_cycle()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        var beforeFirstCycle = 0L;
        robot.Start(() =>
        {
            _ = Nest<Level0>(FreshMethods); // compiled on the bus thread before its first cycle
            beforeFirstCycle = JitInfo.GetCompiledMethodCount(currentThread: true);
        });
        long compiled;
        TimeSpan compileTime;
        try
        {
            Until(() => robot.Cycles > 2, "the first cycles");
            await robot.Slot.Post("something new to compile", () => Nest<Level1>(1));
            (compiled, compileTime) = await robot.Slot.Post("what the thread compiled so far", () => (JitInfo.GetCompiledMethodCount(currentThread: true), JitInfo.GetCompilationTime(currentThread: true)));
        }
        finally
        {
            robot.Stop();
        }

        // Some (the work posted), and not those of before its first cycle (nor other threads'): what stopping the
        // thread compiles afterwards is far less than the methods compiled before the first cycle. The time is
        // counted between the same two points, but it is the thread's wall time in the compiler, which a host
        // holding the virtual CPU stretches (4 ms against 2 ms for all before, on CI): only counts bound it.
        Assert.True(beforeFirstCycle >= FreshMethods);
        Assert.InRange(robot.MethodsCompiledAfterFirstCycle, 1, compiled - (FreshMethods / 2));
        Assert.True(robot.CompileTimeAfterFirstCycle > TimeSpan.Zero, "the posted work's compile time counted");
        Assert.True(compileTime > TimeSpan.Zero);
    }

    private const int FreshMethods = 60;

    /// <summary>Compiles <paramref name="depth"/> methods never compiled before: one per nesting of a value type.</summary>
    private static int Nest<T>(int depth)
        where T : struct => depth == 0 ? 0 : 1 + Nest<Wrap<T>>(depth - 1);

    private static void Until(Func<bool> condition, string what)
    {
        var waited = System.Diagnostics.Stopwatch.StartNew();
        while (!condition())
        {
            Assert.True(waited.Elapsed < TimeSpan.FromSeconds(60), $"no {what} after 60 s");
            Thread.Sleep(1);
        }
    }

    private readonly struct Level0;

    private readonly struct Level1;

    private readonly struct Wrap<T>
        where T : struct;
}
