using System.Globalization;
using RobotControl.Bus.Client;
using RobotControl.Bus.Transports;
using RobotControl.Definitions.Loading;
using RobotControl.Definitions.Model;
using RobotControl.Robot.Bus;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;

namespace RobotControl.Host.Session;

/// <summary>
/// A robot file on a transport: the bus link (serial, USB or TCP on the system clock; or a virtual robot running the
/// module firmware on its own simulated clock), the protocol client on it and the robot layer. The first half of a
/// <see cref="RobotSession"/>; on its own, the session of the bus commands (discover, params, home, jog).
/// </summary>
public sealed class RobotConnection : IDisposable
{
    private RobotConnection(BusClient client, RobotDefinition? robot, VirtualRobot? simulation, ManualTimeProvider? virtualClock, BusRobotOptions? robotOptions = null)
    {
        Client = client;
        Definition = robot;
        Simulation = simulation;
        VirtualClock = virtualClock;
        Robot = robot is null ? null : new BusRobot(robot, client, robotOptions);
    }

    /// <summary>The protocol client.</summary>
    public BusClient Client { get; }

    /// <summary>The robot file (null when a real bus was opened without one).</summary>
    public RobotDefinition? Definition { get; }

    /// <summary>The robot layer (null without a robot file).</summary>
    public BusRobot? Robot { get; }

    /// <summary>The virtual robot on the other end of the link (null on a real bus).</summary>
    public VirtualRobot? Simulation { get; }

    /// <summary>The simulated clock of a virtual bus (null on a real bus, whose clock is the system's).</summary>
    public ManualTimeProvider? VirtualClock { get; }

    /// <summary>The bus's clock: simulated for a virtual bus, else the system clock.</summary>
    public TimeProvider Clock => Client.Time;

    /// <summary>
    /// Opens <paramref name="transport"/> (e.g. <c>serial:/dev/ttyUSB0?baud=1000000</c>, <c>tcp:host:port</c>, or
    /// <c>virtual:&lt;robot file&gt;</c> for a commissioned virtual robot); <paramref name="robotFile"/> names the robot
    /// (optional on a real bus; on a virtual one it overrides the transport's file).
    /// </summary>
    /// <exception cref="FormatException">The transport string is malformed.</exception>
    /// <exception cref="IOException">The device cannot be opened.</exception>
    /// <exception cref="RobotDataException">The robot file is invalid.</exception>
    public static RobotConnection Open(string transport, string? robotFile, BusClientOptions? clientOptions = null)
    {
        var uri = CheckTransport(transport);
        if (uri.Kind == LinkKind.Virtual)
        {
            var robot = RobotLoader.Load(robotFile ?? uri.Target);
            return OpenVirtual(robot, new VirtualRobotOptions { BaudRate = uri.Options.ContainsKey("baud") ? uri.BaudRate : null, Seed = VirtualSeed(uri) }, clientOptions);
        }

        var definition = robotFile is null ? null : RobotLoader.Load(robotFile);
        return OpenReal(LinkFactory.Open(uri), definition, clientOptions);
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

    /// <summary>Opens <paramref name="robot"/> on a real link (the connection owns it) on the system clock.</summary>
    public static RobotConnection OpenReal(IByteLink link, RobotDefinition? robot, BusClientOptions? clientOptions = null, BusRobotOptions? robotOptions = null)
    {
        ArgumentNullException.ThrowIfNull(link);
        return new RobotConnection(new BusClient(link, TimeProvider.System, clientOptions), robot, null, null, robotOptions);
    }

    /// <summary>
    /// Builds the virtual robot of <paramref name="robot"/> on a new simulated clock and opens its bus;
    /// <paramref name="wrapLink"/>, if given, wraps the host's end of the link (e.g. to timestamp frames).
    /// </summary>
    public static RobotConnection OpenVirtual(RobotDefinition robot, VirtualRobotOptions? simulation = null, BusClientOptions? clientOptions = null, Func<IByteLink, TimeProvider, IByteLink>? wrapLink = null, BusRobotOptions? robotOptions = null)
    {
        ArgumentNullException.ThrowIfNull(robot);
        var clock = new ManualTimeProvider();
        var sim = new VirtualRobot(robot, clock, simulation);
        var link = sim.OpenLink();
        return new RobotConnection(new BusClient(wrapLink?.Invoke(link, clock) ?? link, clock, clientOptions), robot, sim, clock, robotOptions);
    }

    /// <summary>The robot layer.</summary>
    /// <exception cref="ArgumentException">The connection has no robot file.</exception>
    public BusRobot RequireRobot() => Robot ?? throw new ArgumentException("this command needs the robot file: add --robot <file> (or use a virtual:<robot file> transport)");

    /// <inheritdoc />
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

        Simulation?.Dispose();
    }

    private static int VirtualSeed(LinkUri uri)
    {
        if (!uri.Options.TryGetValue("seed", out var s))
        {
            return 1;
        }

        return int.TryParse(s, NumberStyles.None, CultureInfo.InvariantCulture, out var seed)
            ? seed
            : throw new FormatException($"transport '{uri}': seed '{s}' must be a whole number from 0 to {int.MaxValue}");
    }
}
