using System.Text.Json.Nodes;
using RobotControl.Definitions.Model;
using RobotControl.Host.Safety;

namespace RobotControl.Host.Tests.Safety;

/// <summary>A foot-pedal plug-in in the teleop graph drives the run level through the supervisor (virtual robot).</summary>
public sealed class PedalTests
{
    [Fact]
    public void A_scripted_pedal_sequence_moves_the_run_level_and_the_goals_change_only_at_pedal_down()
    {
        // pedal1 (teleoperation): down 0.2 s, up 1.3 s, down 1.5 s; pedal2 (E-STOP) pressed at 1.8 s. The scripted
        // hands start moving at 1.0 s.
        var dir = Directory.CreateTempSubdirectory("pedal-");
        SafetyRun run;
        try
        {
            run = SafetyRun.Of(string.Empty, 2.0, GraphWithPedals(dir.FullName, "0.2:1,1.3:0,1.5:1,1.8:3"), supervisor => supervisor.Reset("test"));
        }
        finally
        {
            dir.Delete(recursive: true);
        }

        var levels = run.Safety.RunLevels;
        Assert.Equal(
            [RunLevel.Homing, RunLevel.PedalUp, RunLevel.PedalDown, RunLevel.PedalUp, RunLevel.PedalDown, RunLevel.EStop, RunLevel.Init],
            levels.Select(l => l.To));
        Assert.Equal(RunLevel.Init, levels[0].From);
        Assert.Equal(["pedal", "pedal", "pedal", "pedal", "test"], levels.Skip(2).Select(l => l.Source));
        Assert.Equal(RunLevel.Init, run.Safety.FinalRunLevel); // the operator reset after the last tick
        Assert.Equal(RunLevel.Init, run.FinalLevel);
        var trip = run.Trip(SafetyCheck.Operator);
        Assert.Equal(SafeState.Hold, trip.Action);
        Assert.Single(run.Safety.Trips);

        // Each pedal edge is seen by the first bus cycle after the tick that read it (loop time starts a few ms before
        // the run's origin).
        double At(int i) => levels[i].TimeSeconds;
        var times = string.Join(", ", levels.Skip(2).Select(l => l.TimeSeconds));
        Assert.True(At(2) is >= 0.2 and <= 0.207, times);
        Assert.True(At(3) is >= 1.3 and <= 1.307, times);
        Assert.True(At(4) is >= 1.5 and <= 1.507, times);
        Assert.True(At(5) is >= 1.8 and <= 1.807, times);
        Assert.InRange(trip.TimeSeconds - At(5), 0, 0.001);

        // Outside PEDAL_DOWN the goals do not change once the hold has settled (the move to the held position is the
        // one change, under the step cap); at PEDAL_DOWN teleoperation moves them. The write of the bus cycle that
        // enters PEDAL_DOWN is stamped up to a cycle (2.5 ms) before the transition: it is left out.
        Assert.True(run.GoalsFrozenBetween(0, At(2) - 0.003), "goals moved at PEDAL_UP before the first pedal down");
        Assert.True(run.GoalsFrozenBetween(At(3) + 0.1, At(4) - 0.003), "goals moved at PEDAL_UP after pedal up");
        Assert.True(run.GoalsFrozenBetween(At(5) + 0.1, 2.0), "goals moved at E_STOP");
        Assert.False(run.GoalsFrozenBetween(At(2), At(3)), "teleoperation did not move the goals at the first PEDAL_DOWN");
        Assert.False(run.GoalsFrozenBetween(At(4), At(5)), "teleoperation did not move the goals at the second PEDAL_DOWN");
        Assert.InRange(run.WorstStepOverCap(), 0, 1);
        Assert.All(run.Motors, m => Assert.False(m.DriverEnabled, $"{m.Name} still driven after the reset to INIT"));
    }

    /// <summary>The shipped teleop graph plus a scripted two-pedal box: pedal1 -> robot.pedal, pedal2 -> robot.estop.</summary>
    private static string GraphWithPedals(string dir, string pedalScript)
    {
        var source = Graphs.Path("teleop-lb.json");
        var sourceDir = Path.GetDirectoryName(source)!;
        var graph = JsonNode.Parse(File.ReadAllText(source))!.AsObject();
        graph["robot"] = Path.GetFullPath(Path.Combine(sourceDir, graph["robot"]!.GetValue<string>()));
        foreach (var instance in graph["instances"]!.AsArray())
        {
            if (instance!["settings"]?["script"] is JsonValue script && script.GetValue<string>().StartsWith("trajectories/", StringComparison.Ordinal))
            {
                instance["settings"]!["script"] = Path.Combine(sourceDir, script.GetValue<string>());
            }
        }

        graph["instances"]!.AsArray().Add(JsonNode.Parse($$"""{ "name": "pedals", "type": "foot_pedals", "settings": { "script": "{{pedalScript}}", "pedals": 2 } }"""));
        graph["wires"]!.AsArray().Add(JsonNode.Parse("""{ "from": "pedals.pedal1", "to": "robot.pedal" }"""));
        graph["wires"]!.AsArray().Add(JsonNode.Parse("""{ "from": "pedals.pedal2", "to": "robot.estop" }"""));
        var path = Path.Combine(dir, "teleop-pedals.json");
        File.WriteAllText(path, graph.ToJsonString());
        return path;
    }
}
