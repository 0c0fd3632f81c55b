namespace RobotControl.Robot.Control.Tests;

/// <summary>The robot port's contract (the operator's inputs are not part of it) and the fault flags it reports.</summary>
public sealed class RobotPortTests
{
    [Fact]
    public void The_robot_port_carries_no_operator_input_which_goes_to_the_supervisor_s_operator_port()
    {
        string[] operatorMembers = ["TeleopAllowed", "ReportTick", "ReportInputAge", "ReportInputSpeed", "ReportPedal", "ReportEmergencyStop"];

        Assert.All(operatorMembers, name => Assert.Empty(typeof(IRobotPort).GetMember(name)));
        Assert.All(operatorMembers, name => Assert.Single(typeof(IOperatorPort).GetMember(name)));
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
}
