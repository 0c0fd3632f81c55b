using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.TestSupport;

namespace RobotControl.Modules.Tests;

/// <summary>
/// The one parameter path on a virtual LB-1.0 (real firmware, motors off): the rules refuse before anything reaches the
/// bus, a valid value is written and read back, and a value that comes back different is reported.
/// </summary>
public sealed class ParameterWriterTests : IDisposable
{
    private static readonly ControlTable Table = ControlTable.Firmware;
    private readonly VirtualRobot _sim = new(ShippedRobots.Lb, new ManualTimeProvider());
    private readonly TappedLink _link;
    private readonly BusClient _client;
    private readonly ParameterWriter _writer;

    public ParameterWriterTests()
    {
        _link = new TappedLink(_sim.OpenLink());
        _client = new BusClient(_link);
        _writer = new ParameterWriter(_client, Table);
    }

    [Theory]
    [InlineData("current_limit", 0, 4096, "current_limit = 4096 is outside its range 0..4095 (u16, ADC raw); nothing was written")]
    [InlineData("kp", 5, 300, "kp has motors 0..3, motor 5 given; nothing was written")]
    [InlineData("pot_cal_count", 0, 1, "module 1: motor 0: pot_cal_count 1 must be 0 (no pot homing) or 2..8 points; nothing was written")]
    [InlineData("pot_cal_raw3", 0, 0, "module 1: motor 0: pot calibration points pot_cal_raw0..")]
    [InlineData("model_number", 0, 1, "model_number is read-only; nothing was written")]
    [InlineData("no_such_field", 0, 1, "the control table has no field 'no_such_field'; nothing was written")]
    [InlineData("current_limit", 1, 0, "current_limit = 0 switches the motor's current limit off; a protection goes off only on purpose (robotctl params set --allow-protection-off); nothing was written")]
    [InlineData("speed_limit", 0, 0, "speed_limit = 0 switches the motor's setpoint speed limit off; a protection goes off only on purpose")]
    [InlineData("bus_watchdog", 0, 0, "bus_watchdog = 0 switches the module's bus watchdog (both stages) off; a protection goes off only on purpose")]
    public void A_value_the_rules_refuse_never_reaches_the_bus(string field, int motor, long value, string expected)
    {
        var before = Table.Contains(field) && motor < Table[field].Count ? _writer.Read(1, field, motor) : 0;

        var refused = Assert.Throws<ArgumentException>(() => _writer.Write(1, field, motor, value));

        Assert.StartsWith(expected, refused.Message, StringComparison.Ordinal);
        Assert.Empty(_link.Writes);
        if (Table.Contains(field) && motor < Table[field].Count)
        {
            Assert.Equal(before, _writer.Read(1, field, motor));
        }
    }

    [Fact]
    public void A_current_limit_of_zero_is_written_only_when_the_caller_allows_a_protection_off()
    {
        Assert.NotEqual(0, _writer.Read(1, "current_limit", 1));

        Assert.Equal(0, _writer.Write(1, "current_limit", 1, 0, allowProtectionOff: true));

        Assert.Equal(0, _writer.Read(1, "current_limit", 1));
        Assert.NotEmpty(_link.Writes);
    }

    [Fact]
    public void Position_min_at_or_above_position_max_is_refused_though_the_firmware_would_take_it()
    {
        var max = _writer.Read(1, "position_max", 1);

        var refused = Assert.Throws<ArgumentException>(() => _writer.Write(1, "position_min", 1, max));

        Assert.Equal($"module 1: motor 1: position_min {max} must be below position_max {max}; nothing was written", refused.Message);
        Assert.Empty(_link.Writes);
        Assert.True(_writer.Read(1, "position_min", 1) < max);
    }

    [Fact]
    public void A_valid_value_is_written_once_and_read_back()
    {
        var kp = _writer.Read(1, "kp", 0);

        Assert.Equal(kp + 7, _writer.Write(1, "kp", 0, kp + 7));

        Assert.Equal([((byte)1, Table["kp"].At(0))], _link.Writes);
        Assert.Equal(kp + 7, _writer.Read(1, "kp", 0));
    }

    [Fact]
    public void A_value_that_reads_back_different_is_reported()
    {
        var kp = _writer.Read(1, "kp", 0);
        _link.CorruptAddress = Table["kp"].At(0);

        var wrong = Assert.Throws<IOException>(() => _writer.Write(1, "kp", 0, kp + 7));

        Assert.Equal($"module 1: kp[0] reads back {kp + 8} after writing {kp + 7}", wrong.Message);
    }

    [Fact]
    public void A_module_that_refuses_the_write_is_reported_with_its_error()
    {
        var torque = Table["torque_enable"];
        Assert.Equal(1, _writer.Write(1, "torque_enable", 0, 1));
        var kp = _writer.Read(1, "kp", 0);

        var locked = Assert.Throws<IOException>(() => _writer.Write(1, "kp", 0, kp + 7));

        Assert.Equal($"module 1: writing kp[0] = {kp + 7} failed (Ok, 0x07 access error): the persistent area is locked while torque is on, turn torque off first", locked.Message);
        Assert.Equal(kp, _writer.Read(1, "kp", 0));
        Assert.Equal((byte)1, Assert.Single(_link.Writes, w => w.Address == Table["kp"].At(0)).Id);
        Assert.Contains(((byte)1, torque.At(0)), _link.Writes);
    }

    [Fact]
    public void The_robot_file_s_values_are_all_checked_before_any_is_written()
    {
        var robot = ShippedRobots.Lb;
        var first = robot.Modules.Modules[0];
        var second = robot.Modules.Modules[1];
        var bad = ModuleParameters.For(robot, second, Table).Select(p => p.Field.Name == "pot_cal_count" && p.Motor == 0 ? p with { Value = 1 } : p).ToList();

        var refused = Assert.Throws<ArgumentException>(() => _writer.WriteAll([(first.Id, ModuleParameters.For(robot, first, Table)), (second.Id, bad)]));

        Assert.Equal($"module {second.Id}: motor 0: pot_cal_count 1 must be 0 (no pot homing) or 2..8 points; nothing was written", refused.Message);
        Assert.Empty(_link.Writes);
    }

    [Fact]
    public void The_robot_file_s_values_are_written_and_read_back()
    {
        var robot = ShippedRobots.Lb;
        var modules = robot.Modules.Modules.Select(m => (m.Id, ModuleParameters.For(robot, m, Table))).ToList();

        Assert.Equal(modules.Sum(m => m.Item2.Count), _writer.WriteAll(modules));
        Assert.Equal(modules.Sum(m => m.Item2.Count), _link.Writes.Count);

        _link.CorruptAddress = Table["speed_limit"].At(1);
        var wrong = Assert.Throws<IOException>(() => _writer.WriteAll(modules));
        var speed = ModuleParameters.For(robot, robot.Modules.Modules[0], Table).Single(p => p.Field.Name == "speed_limit" && p.Motor == 1).Value;
        Assert.Equal($"module {robot.Modules.Modules[0].Id}: speed_limit[1] reads back {speed + 1} after writing {speed}", wrong.Message);
    }

    public void Dispose()
    {
        _client.Dispose();
        _sim.Dispose();
    }
}
