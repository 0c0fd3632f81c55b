namespace RobotControl.Cli.Tests.Commands.Bus;

/// <summary>
/// <c>robotctl params</c> never stores a value nobody asked for (issue 18, class 2): each refused write leaves the
/// module's table as it was, read back; and it says so when the link never answers (class 6), and takes the
/// transport once (class 8).
/// </summary>
[Collection(PtyBus.Collection)]
public sealed class ParamsCommandHardeningTests
{
    [Theory]
    [InlineData("current_limit", 0, "65536", "outside its range 0..4095")]
    [InlineData("control_mode", 0, "257", "outside its range 0..1")]
    [InlineData("kp", 0, "-1", "outside its range 0..65535")]
    [InlineData("position_min", 1, "999999999", "must be below position_max")]
    [InlineData("pot_cal_count", 0, "1", "must be 0 (no pot homing) or 2..8")]
    [InlineData("pot_cal_raw3", 0, "0", "strictly increasing or strictly decreasing")]
    [InlineData("baud_rate", 0, "8", "outside its range 0..7")]
    [InlineData("baud_rate", 0, "4", "leave --module out")]
    [InlineData("id", 0, "9", "add --yes to confirm")]
    [InlineData("current_limit", 0, "0", "current_limit = 0 switches the motor's current limit off; a protection goes off only on purpose (robotctl params set --allow-protection-off)")]
    [InlineData("speed_limit", 1, "0", "speed_limit = 0 switches the motor's setpoint speed limit off")]
    [InlineData("bus_watchdog", 0, "0", "bus_watchdog = 0 switches the module's bus watchdog (both stages) off")]
    public void A_value_outside_the_control_table_or_its_rules_is_refused_and_not_stored(string field, int motor, string value, string expected)
    {
        using var bus = new PtyBus();
        var before = bus.Read(1, field, motor);

        var result = bus.Run("params set", "--module", "1", "--field", field, "--motor", motor.ToString(System.Globalization.CultureInfo.InvariantCulture), "--value", value);

        Cli.AssertRefused(result, expected);
        Assert.Equal(before, bus.Read(1, field, motor));
    }

    [Fact]
    public void A_protection_is_switched_off_only_with_the_option_and_then_with_one_warning_naming_it()
    {
        using var bus = new PtyBus();
        Assert.NotEqual(0, bus.Read(2, "current_limit", 0));

        var (code, output, error) = bus.Run("params set", "--module", "2", "--field", "current_limit", "--motor", "0", "--value", "0", "--allow-protection-off");

        Assert.True(code == 0, error);
        var warning = Assert.Single(error.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries));
        Assert.Equal("warning: module 2: current_limit = 0 switches the motor's current limit off (--allow-protection-off)", warning);
        Assert.Contains("current_limit[0] = 0 (read back)", output, StringComparison.Ordinal);
        Assert.Equal(0, bus.Read(2, "current_limit", 0));
    }

    [Fact]
    public void The_option_adds_no_warning_to_a_value_that_switches_nothing_off()
    {
        using var bus = new PtyBus();

        var (code, _, error) = bus.Run("params set", "--module", "2", "--field", "current_limit", "--motor", "0", "--value", "1200", "--allow-protection-off");

        Assert.True(code == 0, error);
        Assert.Equal(string.Empty, error.Trim());
        Assert.Equal(1200, bus.Read(2, "current_limit", 0));
    }

    [Fact]
    public void A_valid_value_is_stored_and_read_back()
    {
        using var bus = new PtyBus();

        var (code, output, error) = bus.Run("params set", "--module", "2", "--field", "kp", "--motor", "0", "--value", "300");

        Assert.True(code == 0, error);
        Assert.Contains("kp[0] = 300 (read back)", output, StringComparison.Ordinal);
        Assert.Equal(300, bus.Read(2, "kp", 0));
    }

    [Theory]
    [InlineData("params", "get")]
    [InlineData("discover")]
    public void An_empty_transport_is_one_line_saying_what_a_transport_looks_like(params string[] command) =>
        Cli.AssertRefused(Cli.Run([.. command, ""]), "transport '': expected kind:target");

    [Fact]
    public void A_module_id_outside_the_bus_range_is_refused_while_parsing() =>
        Cli.AssertRefused(Cli.Run("params", "set", "virtual:" + Cli.RepoFile("hardware/robots/lb-1.0.json"), "--module", "257", "--field", "kp", "--value", "3"), "--module: 257 is outside 0 to 252");

    [Fact]
    public void Params_get_on_a_link_that_never_answers_fails_with_a_message()
    {
        using var silent = new PtyBus(serve: false);

        var result = silent.Run("params get", "--margin-ms", "1");

        Cli.AssertRefused(result, "no module of the robot file answers");
    }

    [Fact]
    public void Params_takes_the_transport_once()
    {
        var transport = "virtual:" + Cli.RepoFile("hardware/robots/lb-1.0.json");

        var (code, output, error) = Cli.Run("params", "get", transport, "--module", "1");
        var twice = Cli.Run("params", transport, "get", transport);

        Assert.True(code == 0, error);
        Assert.Contains("module 1 ", output, StringComparison.Ordinal);
        Assert.NotEqual(0, twice.Code);
    }

    [Fact]
    public void A_bad_seed_in_a_virtual_transport_is_named()
    {
        var transport = "virtual:" + Cli.RepoFile("hardware/robots/lb-1.0.json") + "?seed=abc";

        Cli.AssertRefused(Cli.Run("discover", transport), "seed 'abc'");
    }
}
