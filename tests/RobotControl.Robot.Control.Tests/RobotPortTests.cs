using RobotControl.Hardware.Model;

namespace RobotControl.Robot.Control.Tests;

/// <summary>The robot port's contract as a port without a safety supervisor sees it, and the fault flags it reports.</summary>
public sealed class RobotPortTests
{
    [Fact]
    public void A_port_without_a_supervisor_always_allows_teleoperation_and_ignores_input_age_pedal_and_emergency_stop()
    {
        var bare = new BarePort();
        IRobotPort port = bare;

        Assert.True(port.TeleopAllowed);
        port.ReportInputAge(0, double.MaxValue);
        port.ReportPedal(down: false);
        port.ReportEmergencyStop(pressed: true);

        Assert.True(port.TeleopAllowed);
        Assert.Equal(RobotFaults.None, port.Faults);
        Assert.Equal(0, bare.Calls); // the defaults neither hold nor write: they only tell a supervisor, and there is none
    }

    [Fact]
    public void Each_fault_is_a_bit_of_its_own_so_faults_combine_and_read_back_one_by_one()
    {
        var faults = Enum.GetValues<RobotFaults>().Where(f => f != RobotFaults.None).ToArray();
        Assert.Equal(0, (int)RobotFaults.None);
        Assert.All(faults, f => Assert.Equal(1, System.Numerics.BitOperations.PopCount((uint)f)));
        Assert.Equal(faults.Length, faults.Select(f => (int)f).Distinct().Count());

        var some = RobotFaults.ModuleReset | RobotFaults.WatchdogTripped;
        Assert.Equal([RobotFaults.ModuleReset, RobotFaults.WatchdogTripped], faults.Where(f => some.HasFlag(f)));
        Assert.Equal(RobotFaults.WatchdogTripped, some & ~RobotFaults.ModuleReset);
    }

    [Fact]
    public void The_flags_keep_their_values_through_the_graphs_faults_output_and_print_by_name()
    {
        // The robot node puts the flags on its "faults" output as a number; graphs and recordings read them back.
        Assert.Equal(
            [1, 2, 4, 8, 16, 32, 64],
            new[]
            {
                RobotFaults.ModuleMissing, RobotFaults.ModuleReset, RobotFaults.HardwareError, RobotFaults.WatchdogTripped,
                RobotFaults.SetpointRejected, RobotFaults.BusDegraded, RobotFaults.CurrentLimited,
            }.Select(f => (int)f));
        var all = Enum.GetValues<RobotFaults>().Aggregate((a, b) => a | b);
        Assert.Equal(all, (RobotFaults)(int)(double)(int)all);

        // The run's progress line and the console list the faults by name.
        Assert.Equal("ModuleReset, BusDegraded", (RobotFaults.ModuleReset | RobotFaults.BusDegraded).ToString());
        Assert.Equal("None", RobotFaults.None.ToString());
    }

    /// <summary>A port implementing only what every port must: every call to it is counted.</summary>
    private sealed class BarePort : IRobotPort
    {
        public int Calls { get; private set; }

        public RobotDefinition Definition => throw new NotSupportedException("not needed by these tests");

        public int ArmCount => 2;

        public RobotFaults Faults => RobotFaults.None;

        public void WriteJointSetpoints(int arm, ReadOnlySpan<double> jointsRad) => Calls++;

        public void WriteJawSetpoint(int arm, double jawRad) => Calls++;

        public void ReadJointPositions(int arm, Span<double> jointsRad) => Calls++;

        public void ReadMotorCurrents(int arm, Span<double> currentsA) => Calls++;

        public void HoldPosition() => Calls++;
    }
}
