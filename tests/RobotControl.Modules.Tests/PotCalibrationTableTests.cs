using RobotControl.Bus.Protocol;
using RobotControl.TestSupport;
using RobotControl.Modules;

namespace RobotControl.Modules.Tests;

public sealed class PotCalibrationTableTests
{
    [Fact]
    public void The_table_written_into_a_module_decodes_to_the_same_numbers_and_maps_its_points_exactly()
    {
        var robot = VirtualLb.Lb;
        var module = robot.Modules.Modules[0];
        var motor = module.Motors[0];
        var config = new MotorConfig(robot, module, motor);
        var cal = PotCalibrationTable.For(config);
        Assert.True(cal.IsCalibrated);
        Assert.Equal(PotCalibrationTable.MaxPoints, cal.Count);

        // Write it as the robot file's parameters do, into a persistent-area image, and read it back.
        var table = ControlTable.Firmware;
        var (start, end) = table.PersistentArea;
        var block = new byte[end - start];
        foreach (var p in ModuleParameters.For(robot, module, table).Where(p => p.Field.Name.StartsWith("pot_cal_", StringComparison.Ordinal) && p.Motor == motor.Channel))
        {
            p.Field.Encode(p.Value, block.AsSpan(p.Address - start, p.Field.Size));
        }

        var decoded = PotCalibrationTable.Decode(table, block, start, motor.Channel);
        Assert.Equal((cal.Count, cal.Pos0, cal.Step), (decoded.Count, decoded.Pos0, decoded.Step));
        Assert.Equal(cal.Raw, decoded.Raw);
        for (var k = 0; k < cal.Count; k++)
        {
            Assert.Equal(cal.Pos0 + (k * cal.Step), decoded.PositionAt((int)cal.Raw[k]));
        }

        // Between two points: linear; beyond the table: the nearest end point.
        var mid = (int)((cal.Raw[0] + cal.Raw[1]) / 2);
        Assert.InRange(decoded.PositionAt(mid), Math.Min(cal.Pos0, cal.Pos0 + cal.Step), Math.Max(cal.Pos0, cal.Pos0 + cal.Step));
        var lowEnd = cal.Raw[0] < cal.Raw[^1] ? -1 : 5000;
        Assert.Equal(cal.Pos0, decoded.PositionAt(lowEnd));
        Assert.Equal(0, (decoded with { Count = 1 }).PositionAt(mid));
    }
}
