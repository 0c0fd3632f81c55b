using RobotControl.Bus.Client;
using RobotControl.Bus.Transports;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Control;
using RobotControl.Robot.Events;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.TestSupport;

namespace RobotControl.Robot.Tests.Bus;

/// <summary>
/// A link that fails under the bus thread (an adapter unplugged, a pty hung up): the robot's one path, whoever runs
/// the session. The bus is degraded and every module misses its replies while it lasts, the failure is reported once
/// and then once a second with how many were left out, and everything comes back when the link does.
/// </summary>
public sealed class BusFailureTests
{
    [Fact]
    public void A_failing_link_degrades_the_bus_reports_once_a_second_and_recovers()
    {
        var clock = new ManualTimeProvider();
        using var sim = new VirtualRobot(ShippedRobots.Lb, clock);
        var link = new FailingLink(sim.OpenLink(), clock);
        using var robot = new BusRobot(ShippedRobots.Lb, new BusClient(link, clock));
        robot.Discover();
        robot.EnableTorque(true);
        using var events = robot.Events.Subscribe();
        robot.Start();
        try
        {
            Until(() => robot.Cycles > 20, "cycles before the failure");
            link.Failing = true;
            Until(() => link.FailedWrites > 350, "failed cycles"); // each advances the bus clock 10 ms: 3.5 s of failure

            Assert.True(robot.Faults.HasFlag(RobotFaults.BusDegraded), robot.Faults.ToString());
            Assert.All(robot.Controllers, c => Assert.False(c.Present, $"{c} still counted as answering"));
            var errors = events.ReadAll().OfType<BusError>().ToList();
            Assert.InRange(errors.Count, 3, 5); // the first, then one per second of bus time
            Assert.All(errors, e => Assert.Contains("the test unplugged the adapter", e.Message, StringComparison.Ordinal));
            Assert.Contains(errors.Skip(1), e => e.Message.Contains("more failed cycles since the last report", StringComparison.Ordinal));

            link.Failing = false;
            Until(() => robot.Controllers.All(c => c.Present) && !robot.Faults.HasFlag(RobotFaults.BusDegraded), "the modules to answer again");
            Assert.Equal(robot.Controllers.Count, events.ReadAll().OfType<ModuleAnswersAgain>().Count());
        }
        finally
        {
            robot.Stop();
        }
    }

    private static void Until(Func<bool> condition, string what)
    {
        var waited = System.Diagnostics.Stopwatch.StartNew();
        while (!condition())
        {
            Assert.True(waited.Elapsed < TimeSpan.FromSeconds(60), $"no {what} after 60 s");
            Thread.Sleep(5);
        }
    }

    /// <summary>The virtual link, failing every write while <see cref="Failing"/> (the bus clock moves 10 ms a failure, as the bus thread's pause would).</summary>
    private sealed class FailingLink(IByteLink inner, ManualTimeProvider clock) : IByteLink
    {
        private int _failed;

        public volatile bool Failing;

        public int FailedWrites => Volatile.Read(ref _failed);

        public string Description => inner.Description;

        public int BaudRate => inner.BaudRate;

        public void Write(ReadOnlySpan<byte> data)
        {
            if (Failing)
            {
                Interlocked.Increment(ref _failed);
                clock.Advance(TimeSpan.FromMilliseconds(10));
                throw new IOException("the test unplugged the adapter");
            }

            inner.Write(data);
        }

        public int Read(Span<byte> buffer, TimeSpan timeout) => inner.Read(buffer, timeout);

        public void DiscardInput() => inner.DiscardInput();

        public void Dispose() => inner.Dispose();
    }
}
