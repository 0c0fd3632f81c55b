using System.Diagnostics;
using RobotControl.Bus.Client;
using RobotControl.Bus.Transports;
using RobotControl.Bus.Transports.Serial;
using RobotControl.Robot.Bus;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.TestSupport;

namespace RobotControl.Simulation.Tests.EndToEnd;

/// <summary>
/// A virtual robot served on a pseudo-terminal in real time, driven through the serial transport like a USB-RS485
/// adapter: discover, home, move a joint, read it back.
/// </summary>
public sealed class PtyEndToEndTests
{
    private const double Deg = Math.PI / 180;

    [Fact]
    public void Host_drives_the_virtual_robot_through_its_own_pty()
    {
        using var pty = PseudoTerminal.Create();
        Assert.StartsWith("/dev/pts/", pty.SlavePath, StringComparison.Ordinal);
        RunScenario(pty, pty.SlavePath);
    }

    [Fact]
    public void Host_drives_the_virtual_robot_through_a_socat_pty_pair()
    {
        var dir = Directory.CreateTempSubdirectory("rcpty");
        var simEnd = Path.Combine(dir.FullName, "sim");
        var hostEnd = Path.Combine(dir.FullName, "host");
        using var socat = Process.Start(new ProcessStartInfo("socat", $"pty,raw,echo=0,link={simEnd} pty,raw,echo=0,link={hostEnd}") { RedirectStandardError = true })!;
        try
        {
            var waited = Stopwatch.StartNew();
            while (!(File.Exists(simEnd) && File.Exists(hostEnd)) && waited.Elapsed < TimeSpan.FromSeconds(5))
            {
                Thread.Sleep(20);
            }

            using var port = SerialLink.Open(simEnd, 1_000_000);
            RunScenario(port, hostEnd);
        }
        finally
        {
            socat.Kill();
            socat.WaitForExit();
            dir.Delete(recursive: true);
        }
    }

    private static void RunScenario(IByteLink port, string hostDevice)
    {
        var elbowStart = 60 * Deg;
        var options = new VirtualRobotOptions { InitialJointsRad = [[0, 0, 0, elbowStart, 0], [0, 0, 0, 90 * Deg, 0]] };
        using var sim = new VirtualRobot(VirtualLb.Lb, new ManualTimeProvider(), options);
        using var stop = new CancellationTokenSource();
        var server = new Thread(() => sim.Serve(port, stop.Token)) { IsBackground = true };
        server.Start();
        try
        {
            var link = LinkFactory.Open($"serial:{hostDevice}?baud=1000000");
            var clientOptions = new BusClientOptions { ResponseMargin = TimeSpan.FromMilliseconds(50), DiscoveryWindow = TimeSpan.FromMilliseconds(100) };
            using var robot = new BusRobot(VirtualLb.Lb, new BusClient(link, TimeProvider.System, clientOptions));

            var discovery = robot.Discover();
            Assert.True(discovery.AllAsConfigured, string.Join("\n", discovery.Lines()));

            var homing = robot.Home();
            var elbowHome = homing.Single(h => h.Motor.Config.FullName == "right.elbow");
            Assert.InRange(elbowHome.PositionRad - elbowStart, -0.5 * Deg, 0.5 * Deg);

            robot.RunFor(TimeSpan.FromMilliseconds(50)); // warm the cycle up (JIT) before the watchdog is armed
            robot.EnableTorque(true);
            var target = elbowStart + (10 * Deg);
            Span<double> q = stackalloc double[5];
            robot.ReadJointPositions(0, q);
            q[3] = target;
            robot.WriteJointSetpoints(0, q);
            var deadline = Stopwatch.StartNew();
            while (deadline.Elapsed < TimeSpan.FromSeconds(4) && Math.Abs(robot.Motor("right.elbow").PositionRad - target) > 0.3 * Deg)
            {
                robot.RunCycle();
                if (robot.Faults.HasFlag(RobotControl.Robot.Control.RobotFaults.WatchdogTripped))
                {
                    // A loaded machine can stall this process longer than the bus watchdog's second stage: the modules
                    // stop, as they must; acknowledge and go on.
                    robot.ClearFaults();
                }
                else if (robot.ModulesHolding > 0)
                {
                    // A shorter stall (past the first stage): the modules hold and refuse the goals until acknowledged.
                    robot.RequestHoldAcknowledgement();
                }
            }

            robot.RunFor(TimeSpan.FromMilliseconds(100));
            robot.ReadJointPositions(0, q);
            Assert.InRange(q[3] - target, -0.5 * Deg, 0.5 * Deg);
            Assert.InRange(sim.Axis(0, "elbow").OutputAngleRad - target, -1.5 * Deg, 1.5 * Deg);
        }
        finally
        {
            stop.Cancel();
            server.Join();
        }
    }
}
