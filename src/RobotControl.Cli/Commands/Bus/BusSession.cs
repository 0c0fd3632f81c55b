using RobotControl.Bus.Client;
using RobotControl.Bus.Transports;
using RobotControl.Hardware.Loading;
using RobotControl.Hardware.Model;
using RobotControl.Robot.Bus;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// A bus opened from a transport string for one command: a real link (serial, usb, tcp) on the system clock, or
/// <c>virtual:&lt;robot file&gt;</c>, a commissioned virtual robot on its simulated clock.
/// </summary>
internal sealed class BusSession : IDisposable
{
    private readonly VirtualRobot? _sim;

    private BusSession(BusClient client, RobotDefinition? robot, VirtualRobot? sim)
    {
        Client = client;
        Definition = robot;
        _sim = sim;
        Robot = robot is null ? null : new BusRobot(robot, client);
    }

    public BusClient Client { get; }

    public RobotDefinition? Definition { get; }

    /// <summary>The robot layer (null without a robot file).</summary>
    public BusRobot? Robot { get; }

    /// <summary>Opens <paramref name="transport"/>; <paramref name="robotFile"/> names the robot on a real bus.</summary>
    /// <exception cref="FormatException">The transport string is malformed.</exception>
    /// <exception cref="IOException">The device cannot be opened.</exception>
    /// <exception cref="RobotDataException">The robot file is invalid.</exception>
    public static BusSession Open(string transport, string? robotFile, TimeSpan responseMargin)
    {
        var uri = CheckTransport(transport);
        var options = new BusClientOptions { ResponseMargin = responseMargin };
        if (uri.Kind == LinkKind.Virtual)
        {
            var robot = RobotLoader.Load(robotFile ?? uri.Target);
            var clock = new ManualTimeProvider();
            var seed = VirtualSeed(uri);
            var sim = new VirtualRobot(robot, clock, new VirtualRobotOptions { BaudRate = uri.Options.ContainsKey("baud") ? uri.BaudRate : null, Seed = seed });
            return new BusSession(new BusClient(sim.OpenLink(), clock, options), robot, sim);
        }

        var definition = robotFile is null ? null : RobotLoader.Load(robotFile);
        return new BusSession(new BusClient(LinkFactory.Open(uri), TimeProvider.System, options), definition, null);
    }

    /// <summary>Parses <paramref name="transport"/> and checks what <see cref="LinkUri"/> leaves to the virtual robot (its <c>seed</c>).</summary>
    /// <exception cref="FormatException">The transport is malformed; the message names the part.</exception>
    public static LinkUri CheckTransport(string transport)
    {
        var uri = LinkUri.Parse(transport);
        if (uri.Kind == LinkKind.Virtual)
        {
            VirtualSeed(uri);
        }
        else if (uri.Options.ContainsKey("seed") || uri.Options.ContainsKey("realtime"))
        {
            throw new FormatException($"transport '{transport}': seed and realtime apply to virtual: transports only");
        }

        return uri;
    }

    private static int VirtualSeed(LinkUri uri)
    {
        if (!uri.Options.TryGetValue("seed", out var s))
        {
            return 1;
        }

        return int.TryParse(s, System.Globalization.NumberStyles.None, System.Globalization.CultureInfo.InvariantCulture, out var seed)
            ? seed
            : throw new FormatException($"transport '{uri}': seed '{s}' must be a whole number from 0 to {int.MaxValue}");
    }

    public BusRobot RequireRobot() => Robot ?? throw new ArgumentException("this command needs the robot file: add --robot <file> (or use a virtual:<robot file> transport)");

    public void Dispose()
    {
        if (Robot is not null)
        {
            Robot.Dispose();
        }
        else
        {
            Client.Dispose();
        }

        _sim?.Dispose();
    }
}
