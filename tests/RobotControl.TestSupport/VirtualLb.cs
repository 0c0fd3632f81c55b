using RobotControl.Hardware.Loading;
using System.Text.Json.Nodes;
using RobotControl.Bus.Client;
using RobotControl.Hardware.Model;
using RobotControl.Robot.Bus;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;

namespace RobotControl.TestSupport;

/// <summary>A virtual LB-1.0 and the robot layer on it, on a manual clock.</summary>
public sealed class VirtualLb : IDisposable
{
    public VirtualLb(VirtualRobotOptions? options = null, RobotDefinition? hostView = null, bool start = true)
    {
        Definition = ShippedRobots.Lb;
        Clock = new ManualTimeProvider();
        Sim = new VirtualRobot(Definition, Clock, options);
        Robot = new BusRobot(hostView ?? Definition, new BusClient(Sim.OpenLink(), Clock));
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
    public static RobotDefinition MisconfiguredHostView()
    {
        var json = JsonNode.Parse(File.ReadAllText(RepositoryPaths.Robot("lb-1.0.json")))!;
        var layout = json["modules"]!["layout"]!.AsArray();
        layout.RemoveAt(2);
        foreach (var m in layout)
        {
            if ((int)m!["id"]! == 13)
            {
                m["id"] = 20;
            }
        }

        return RobotLoader.LoadFromText(json.ToJsonString(), RepositoryPaths.Robot("edited.json"));
    }

    public void Dispose()
    {
        Robot.Dispose();
        Sim.Dispose();
    }
}
