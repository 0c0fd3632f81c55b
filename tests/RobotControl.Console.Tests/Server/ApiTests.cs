using System.Net;
using System.Net.Http.Json;
using System.Text;

namespace RobotControl.WebConsole.Tests.Server;

[Collection(ConsoleCollection.Name)]
public sealed class ApiTests(ConsoleFixture console)
{
    [Fact]
    public async Task Status_names_the_robot_transport_modules_and_loop()
    {
        using var http = console.Client("status-reader");
        var reply = await http.GetFromJsonAsync<System.Text.Json.JsonElement>("api/status");
        var s = reply.GetProperty("status");
        Assert.Equal("LB-1.0", s.GetProperty("robot").GetString());
        Assert.StartsWith("virtual:", s.GetProperty("transport").GetString(), StringComparison.Ordinal);
        Assert.Equal(6, s.GetProperty("modulesFound").GetInt32());
        Assert.Equal(1000, s.GetProperty("loopRateHz").GetDouble());
        Assert.True(s.GetProperty("ticks").GetInt64() > 0);
        Assert.True(s.GetProperty("robotState").GetString() == "PEDAL_UP", $"run level {s.GetProperty("robotState")}, faults {s.GetProperty("faults")}"); // the safety supervisor's
        Assert.Equal("Enabled", s.GetProperty("robotLayer").GetString());
        Assert.Equal("running", s.GetProperty("session").GetString());
    }

    [Fact]
    public async Task Each_module_card_says_why_the_module_last_started()
    {
        using var http = console.Client("reset-cause-reader");
        var controllers = await http.GetFromJsonAsync<System.Text.Json.JsonElement>("api/controllers");

        // Every module of the virtual robot powered on before the console connected (another test may have rebooted one since).
        foreach (var c in controllers.EnumerateArray())
        {
            var cause = c.GetProperty("resetCause").GetString();
            Assert.True(cause is "power-on (before the host connected)" or "software (while connected)", $"module {c.GetProperty("id")}: last reset \"{cause}\"");
        }
    }

    [Fact]
    public async Task A_watching_client_cannot_jog()
    {
        using var operatorClient = await console.Operator("operator-a");
        using var watcher = console.Client("watcher-b");
        var response = await watcher.PostAsJsonAsync("api/motors/right.elbow/jog", new { degPerS = 5 });
        Assert.Equal(HttpStatusCode.Forbidden, response.StatusCode);
        Assert.Contains("another console holds the operator role", await response.Content.ReadAsStringAsync(), StringComparison.Ordinal);
        Assert.Equal(HttpStatusCode.Conflict, (await watcher.PostAsync("api/operator", null)).StatusCode);
        Assert.False((await ConsoleFixture.Motor(watcher, "right.elbow")).GetProperty("manual").GetBoolean());
        console.ReleaseOperator();
    }

    [Fact]
    public async Task A_watching_client_stops_another_consoles_jog()
    {
        using var operatorClient = await console.Operator("operator-jogging");
        using var watcher = console.Client("watcher-stopping");
        (await operatorClient.PostAsJsonAsync("api/pedal", new { down = true })).EnsureSuccessStatusCode();
        (await operatorClient.PostAsJsonAsync("api/motors/right.elbow/jog", new { degPerS = 5 })).EnsureSuccessStatusCode();

        var response = await watcher.PostAsync("api/motors/right.elbow/stop", null);

        Assert.Equal(HttpStatusCode.OK, response.StatusCode);
        Assert.Contains("jog stopped, holding", await response.Content.ReadAsStringAsync(), StringComparison.Ordinal);
        Assert.Equal("operator-jogging", console.Server.Operator.Holder); // the role stays where it was
        (await operatorClient.PostAsync("api/motors/right.elbow/release", null)).EnsureSuccessStatusCode();
        (await operatorClient.PostAsJsonAsync("api/pedal", new { down = false })).EnsureSuccessStatusCode();
        console.ReleaseOperator();
    }

    [Fact]
    public async Task Bad_input_gets_4xx_with_a_message_and_nothing_applied()
    {
        using var http = await console.Operator("operator-bad-input");
        var before = await ConsoleFixture.Motor(http, "right.elbow");
        var kp = ConsoleFixture.Parameter(before, "kp");
        var limit = ConsoleFixture.Parameter(before, "current_limit");

        async Task Expect(HttpStatusCode code, HttpResponseMessage response, string fragment)
        {
            Assert.Equal(code, response.StatusCode);
            Assert.Contains(fragment, await response.Content.ReadAsStringAsync(), StringComparison.Ordinal);
        }

        await Expect(HttpStatusCode.NotFound, await http.PostAsJsonAsync("api/motors/right.nosuch/jog", new { degPerS = 5 }), "no motor 'right.nosuch'");
        await Expect(HttpStatusCode.BadRequest, await http.PostAsJsonAsync("api/motors/right.elbow/setpoint", new { deg = 1000 }), "outside");
        await Expect(HttpStatusCode.BadRequest, await http.PostAsJsonAsync("api/motors/right.elbow/jog", new { degPerS = 1e6 }), "speed limit");
        await Expect(HttpStatusCode.BadRequest, await http.PutAsync("api/motors/right.elbow/parameters/kp", new StringContent("{\"value\": ", Encoding.UTF8, "application/json")), "malformed JSON");
        await Expect(HttpStatusCode.BadRequest, await http.PutAsync("api/motors/right.elbow/parameters/kp", new StringContent("{\"valu\": 3}", Encoding.UTF8, "application/json")), "kp");
        await Expect(HttpStatusCode.BadRequest, await http.PutAsJsonAsync("api/motors/right.elbow/parameters/current_limit", new { value = 1e6 }), "is outside its range 0..4095");
        await Expect(HttpStatusCode.BadRequest, await http.PutAsJsonAsync("api/motors/right.elbow/parameters/kp", new { value = -1 }), "is outside its range 0..65535");
        await Expect(HttpStatusCode.NotFound, await http.PutAsJsonAsync("api/motors/right.elbow/parameters/nosuch", new { value = 1 }), "no parameter 'nosuch'");
        await Expect(HttpStatusCode.NotFound, await http.PostAsync("api/controllers/99/reboot", null), "no controller 99");

        var reload = await http.PostAsync($"api/controllers/{(await ControllerOf(http, "right.elbow"))}/reload", null);
        reload.EnsureSuccessStatusCode();
        var after = await ConsoleFixture.Motor(http, "right.elbow");
        Assert.Equal(kp, ConsoleFixture.Parameter(after, "kp"));
        Assert.Equal(limit, ConsoleFixture.Parameter(after, "current_limit"));
        Assert.False(after.GetProperty("manual").GetBoolean());
        console.ReleaseOperator();
    }

    [Theory]
    [InlineData("current_limit", "current_limit = 0 switches the motor's current limit off")]
    [InlineData("speed_limit", "speed_limit = 0 switches the motor's setpoint speed limit off")]
    public async Task A_parameter_write_that_switches_a_protection_off_is_refused_and_nothing_written(string parameter, string off)
    {
        // Issue 29: a current limit of 0 A came back 200 "written to FRAM", and teleoperation ran without a limiter.
        using var http = await console.Operator("operator-protection-off");
        var before = ConsoleFixture.Parameter(await ConsoleFixture.Motor(http, "right.elbow"), parameter);

        var response = await http.PutAsJsonAsync($"api/motors/right.elbow/parameters/{parameter}", new { value = 0 });

        Assert.Equal(HttpStatusCode.BadRequest, response.StatusCode);
        var body = await response.Content.ReadAsStringAsync();
        Assert.Contains(off, body, StringComparison.Ordinal);
        Assert.DoesNotContain("written to FRAM", body, StringComparison.Ordinal);
        (await http.PostAsync($"api/controllers/{(await ControllerOf(http, "right.elbow"))}/reload", null)).EnsureSuccessStatusCode();
        Assert.Equal(before, ConsoleFixture.Parameter(await ConsoleFixture.Motor(http, "right.elbow"), parameter));
        console.ReleaseOperator();
    }

    private static async Task<int> ControllerOf(HttpClient http, string motor)
    {
        var controllers = await http.GetFromJsonAsync<System.Text.Json.JsonElement>("api/controllers");
        return controllers.EnumerateArray().First(c => c.GetProperty("motors").EnumerateArray().Any(m => m.GetProperty("name").GetString() == motor)).GetProperty("id").GetInt32();
    }
}
