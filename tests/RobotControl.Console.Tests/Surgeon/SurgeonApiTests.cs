using System.Net;
using System.Net.Http.Json;
using System.Text.Json;

namespace RobotControl.WebConsole.Tests.Surgeon;

/// <summary>The surgeon's view's endpoints against its own virtual-robot console.</summary>
[Collection(SurgeonCollection.Name)]
public sealed class SurgeonApiTests(SurgeonFixture console)
{
    [Fact]
    public async Task Hands_and_pedals_are_found_by_plug_in_type_in_the_graph()
    {
        using var http = await console.Client("surgeon-reader", operate: false);
        var view = await http.GetFromJsonAsync<JsonElement>("api/surgeon");
        var hands = view.GetProperty("hands").EnumerateArray().ToDictionary(h => h.GetProperty("arm").GetString()!);
        Assert.Equal(["right", "left"], hands.Keys);
        var right = hands["right"];
        Assert.Equal("clutch_right.engaged", right.GetProperty("clutchSignal").GetString());
        Assert.Equal(JsonValueKind.Null, right.GetProperty("lockSignal").ValueKind); // the teleop graph has no haptic lock
        Assert.Equal("scaling_right", right.GetProperty("scaling").GetString());
        Assert.Equal(0.01, right.GetProperty("scaleMin").GetDouble());
        Assert.Equal(10, right.GetProperty("scaleMax").GetDouble());
        Assert.Equal(["walls_right.fx", "walls_right.fy", "walls_right.fz"], right.GetProperty("wallSignals").EnumerateArray().Select(s => s.GetString()));
        Assert.Equal("ik_right.error_mm", right.GetProperty("reachErrorSignal").GetString());
        Assert.Equal("walls_left.fx", hands["left"].GetProperty("wallSignals")[0].GetString());
        var pedals = view.GetProperty("pedals").EnumerateArray().ToDictionary(p => p.GetProperty("signal").GetString()!, p => p.GetProperty("drives").GetString());
        Assert.Equal("run level (pedal)", pedals["pedals.pedal1"]);
        Assert.Equal("right clutch", pedals["pedals.pedal2"]);
    }

    [Fact]
    public async Task The_workspace_is_sampled_from_the_kinematics_around_each_arm()
    {
        using var http = await console.Client("workspace-reader", operate: false);
        var arms = (await http.GetFromJsonAsync<JsonElement>("api/workspace")).GetProperty("arms").EnumerateArray().ToList();
        Assert.Equal(["right", "left"], arms.Select(a => a.GetProperty("arm").GetString()));
        Assert.Equal("right_tool", arms[0].GetProperty("toolLink").GetString());
        var right = arms[0].GetProperty("interior").EnumerateArray().Select(v => v.GetDouble()).ToList();
        var left = arms[1].GetProperty("interior").EnumerateArray().Select(v => v.GetDouble()).ToList();
        Assert.True(right.Count >= 3000 && right.Count % 3 == 0);

        // Mirrored arms: the left cloud is the right one reflected in the x-z plane of the body (y negated), in metres.
        Assert.Equal(right.Count, left.Count);
        for (var i = 0; i < right.Count; i += 3)
        {
            Assert.Equal(right[i], left[i], 5);
            Assert.Equal(-right[i + 1], left[i + 1], 5);
            Assert.Equal(right[i + 2], left[i + 2], 5);
        }

        Assert.InRange(right.Max(Math.Abs), 0.01, 1);
    }

    [Fact]
    public async Task The_scale_is_refused_unless_the_clutch_is_held_and_a_change_moves_the_target_without_a_jump()
    {
        using var http = await console.Client("scale-operator", operate: true);
        const string Clutch = "clutch_right.engaged";

        await SurgeonFixture.Until(() => console.Latest(Clutch) < 0.5, "the right clutch released");
        var refused = await http.PutAsJsonAsync("api/hands/right/scale", new { value = 0.8 });
        Assert.Equal(HttpStatusCode.UnprocessableEntity, refused.StatusCode);
        var message = (await refused.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("error").GetString()!;
        Assert.Equal("the right scale factor changes only while the right clutch is held (clutch_right is released)", message);
        var before = await Scale(http);

        await SurgeonFixture.Until(() => console.Latest(Clutch) >= 0.5, "the right clutch held");
        var target = before < 0.7 ? 0.8 : 0.4;
        var accepted = await http.PutAsJsonAsync("api/hands/right/scale", new { value = target });
        Assert.Equal(HttpStatusCode.OK, accepted.StatusCode);
        Assert.Equal(target, await Scale(http), 9);
        // The haptic walls undo the ratio in effect: the graph wires scaling_right.ratio to walls_right.scale_ratio.
        await SurgeonFixture.Until(() => console.Latest("scaling_right.ratio") == target, "the ratio in effect reaches the walls");

        // After the clutch is released the target (the clutch's output) moves on from where it stopped: no tick-to-tick
        // step near the change of ratio (a change while released would step by the ratio change times the hand's
        // displacement from the scaling reference point).
        var from = console.Session.Signals.Written;
        await SurgeonFixture.Until(() => console.Latest(Clutch) < 0.5, "the right clutch released again");
        await Task.Delay(300);
        var ring = console.Session.Signals;
        var columns = new[] { "clutch_right.x", "clutch_right.y", "clutch_right.z" }.Select(ring.IndexOf).ToList();
        var rows = ring.Read(from, columns, ring.Capacity);
        Assert.True(rows.Times.Count > 1000, $"{rows.Times.Count} rows");
        var largest = columns.Select((_, c) => rows.Values[c].Zip(rows.Values[c].Skip(1), (a, b) => Math.Abs(b - a)).Max()).Max();
        Assert.True(largest < 0.5, $"the target stepped {largest:F3} mm in one tick");

        // Bad input: 400 outside the ratio setting's range, 404 for an arm no hand drives, 403 for a watcher.
        Assert.Equal(HttpStatusCode.BadRequest, (await http.PutAsJsonAsync("api/hands/right/scale", new { value = 50 })).StatusCode);
        Assert.Equal(HttpStatusCode.NotFound, (await http.PutAsJsonAsync("api/hands/middle/scale", new { value = 1 })).StatusCode);
        using var watcher = await console.Client("scale-watcher", operate: false);
        Assert.Equal(HttpStatusCode.Forbidden, (await watcher.PutAsJsonAsync("api/hands/right/scale", new { value = 1 })).StatusCode);
        Assert.Equal(target, await Scale(http), 9);
    }

    private static async Task<double> Scale(HttpClient http)
    {
        var view = await http.GetFromJsonAsync<JsonElement>("api/surgeon");
        return view.GetProperty("hands").EnumerateArray().Single(h => h.GetProperty("arm").GetString() == "right").GetProperty("scale").GetDouble();
    }
}
