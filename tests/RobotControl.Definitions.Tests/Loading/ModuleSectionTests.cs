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
    public void A_current_limit_the_module_would_keep_as_0_counts_is_refused_in_one_line_naming_file_and_path()
    {
        // Issue 29: the module keeps the limit in current ADC counts and 0 counts switches its limiter off. Module 2's
        // sense is 0.25 A at 4095 counts, so 0.00003 A would round to 0 (the field's own minimum is 0.001 A: use a
        // wide sense range to reach it).
        var json = RobotFiles.Json("lb-1.0.json");
        var module = json["modules"]!["layout"]![1]!;
        module["current_sense_full_scale_A"] = 10;
        module["motors"]![0]!["current_limit_A"] = 0.001;
        var file = RobotFiles.Shipped("zero-limit.json");

        var ex = Assert.Throws<RobotDataException>(() => RobotLoader.LoadFromText(json.ToJsonString(), file));

        var error = Assert.Single(ex.Errors);
        Assert.Equal("$.modules.layout[1].motors[0].current_limit_A", error.Path);
        Assert.Equal("is 0.001 A, which the module keeps as 0 current counts (current_sense_full_scale_A 10 A = 4095 counts), and a current limit of 0 switches the module's current limiter off; give at least 0.00122 A", error.Message);
        Assert.Equal($"{file}: {error.Path}: {error.Message}", ex.Message);

        module["motors"]![0]!["current_limit_A"] = 0.0013; // 0.53 counts: kept as 1
        Assert.Equal(0.0013, RobotLoader.LoadFromText(json.ToJsonString(), file).Modules.ById(2)!.Motors[0].CurrentLimitA);
    }

    [Fact]
    public void A_current_limit_of_0_is_refused_in_one_line_naming_file_and_path()
    {
        var json = RobotFiles.Json("lb-1.0.json");
        json["modules"]!["layout"]![0]!["motors"]![1]!["current_limit_A"] = 0;
        var file = RobotFiles.Shipped("zero-limit.json");

        var ex = Assert.Throws<RobotDataException>(() => RobotLoader.LoadFromText(json.ToJsonString(), file));

        var error = Assert.Single(ex.Errors);
        Assert.Equal("$.modules.layout[0].motors[1].current_limit_A", error.Path);
        Assert.StartsWith("is 0; must be at least 0.001", error.Message, StringComparison.Ordinal);
        Assert.Equal($"{file}: {error.Path}: {error.Message}", ex.Message);
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
