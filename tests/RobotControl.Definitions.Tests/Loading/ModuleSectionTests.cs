using System.Text.Json.Nodes;
using RobotControl.Definitions.Loading;

namespace RobotControl.Definitions.Tests.Loading;

public sealed class ModuleSectionTests
{
    [Fact]
    public void Both_robot_files_describe_their_modules()
    {
        foreach (var file in new[] { "lb-1.0.json", "crb-1.0.json" })
        {
            var robot = RobotLoader.Load(RobotFiles.Shipped(file));
            Assert.Equal(6, robot.Modules.Modules.Count);
            Assert.Equal([1, 2, 3, 11, 12, 13], robot.Modules.Modules.Select(m => (int)m.Id));
            Assert.Equal(robot.Actuators.Count * 2, robot.Modules.Modules.Sum(m => m.Motors.Count));
            Assert.Equal("left upper arm", robot.Modules.ById(12)!.Name);
        }
    }

    [Fact]
    public void Errors_name_the_field_by_its_JSON_path()
    {
        var json = RobotFiles.Json("lb-1.0.json");
        var layout = json["modules"]!["layout"]!.AsArray();
        layout[1]!["id"] = 1;                                   // duplicate
        layout[2]!["arm"] = "middle";                           // no such arm
        layout[0]!["motors"]![1]!["actuator"] = "shoulder_9";   // no such actuator
        layout[3]!["motors"]![0]!["current_limit_A"] = 5;       // above the sense range
        layout[4]!["motors"]![0]!["pot"]!["bow_counts"] = 2000; // not monotonic
        layout[5]!["motors"]![0]!["speed_limit_deg_s"] = null;

        var ex = Assert.Throws<RobotDataException>(() => RobotLoader.LoadFromText(json.ToJsonString(), RobotFiles.Shipped("bad.json")));
        var paths = ex.Errors.Select(e => e.Path).ToArray();
        Assert.Contains("$.modules.layout[1].id", paths);
        Assert.Contains("$.modules.layout[2].arm", paths);
        Assert.Contains("$.modules.layout[0].motors[1].actuator", paths);
        Assert.Contains("$.modules.layout[3].motors[0].current_limit_A", paths);
        Assert.Contains("$.modules.layout[4].motors[0].pot.bow_counts", paths);
        Assert.Contains("$.modules.layout[5].motors[0].speed_limit_deg_s", paths);
    }
}
