using RobotControl.Definitions.Loading;
using System.Text.Json.Nodes;
using RobotControl.Bus.Client;
using RobotControl.Bus.Transports;
using RobotControl.Definitions.Model;
using RobotControl.Robot.Bus;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;

namespace RobotControl.TestSupport;

/// <summary>A virtual LB-1.0 and the robot layer on it, on a manual clock.</summary>
public sealed class VirtualLb : IDisposable
{
    /// <summary>
    /// A virtual LB (<paramref name="options"/>) and the robot layer on it as <paramref name="hostView"/> describes it
    /// (default: the LB's file), with <paramref name="robotOptions"/>; <paramref name="link"/> puts something between
    /// the host and the virtual bus (it gets the virtual link); the clock starts at <paramref name="clockAt"/> (default 0).
    /// With <paramref name="start"/>, discovered and motors on.
    /// </summary>
    public VirtualLb(VirtualRobotOptions? options = null, RobotDefinition? hostView = null, bool start = true, BusRobotOptions? robotOptions = null, Func<IByteLink, IByteLink>? link = null, TimeSpan clockAt = default)
    {
        Definition = ShippedRobots.Lb;
        Clock = new ManualTimeProvider();
        Clock.Advance(clockAt);
        Sim = new VirtualRobot(Definition, Clock, options);
        var hostLink = Sim.OpenLink();
        Robot = new BusRobot(hostView ?? Definition, new BusClient(link is null ? hostLink : link(hostLink), Clock), robotOptions);
        if (start)
        {
            Discovery = Robot.Discover();
            Robot.EnableTorque(true);
        }
    }

    public static RobotDefinition Lb => ShippedRobots.Lb;

    public RobotDefinition Definition { get; }

    public ManualTimeProvider Clock { get; }

    public VirtualRobot Sim { get; }

    public BusRobot Robot { get; }

    public DiscoveryReport? Discovery { get; }

    /// <summary>The LB as a misconfigured host sees it: the left forearm moved to ID 20 (not on the bus), the right forearm (ID 3) forgotten.</summary>
    public static RobotDefinition MisconfiguredHostView() => EditedLb(json =>
    {
        var layout = json["modules"]!["layout"]!.AsArray();
        layout.RemoveAt(2);
        foreach (var m in layout)
        {
            if ((int)m!["id"]! == 13)
            {
                m["id"] = 20;
            }
        }
    });

    /// <summary>The LB's robot file after <paramref name="edit"/> (of its JSON), loaded as <c>edited.json</c>.</summary>
    public static RobotDefinition EditedLb(Action<JsonNode> edit)
    {
        ArgumentNullException.ThrowIfNull(edit);
        var json = JsonNode.Parse(File.ReadAllText(RepositoryPaths.Robot("lb-1.0.json")))!;
        edit(json);
        return RobotLoader.LoadFromText(json.ToJsonString(), RepositoryPaths.Robot("edited.json"));
    }

    public void Dispose()
    {
        Robot.Dispose();
        Sim.Dispose();
    }
}
