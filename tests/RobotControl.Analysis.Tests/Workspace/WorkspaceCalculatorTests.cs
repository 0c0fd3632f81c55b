using RobotControl.Analysis.Workspace;

namespace RobotControl.Analysis.Tests.Workspace;

public sealed class WorkspaceCalculatorTests
{
    [Fact]
    public void Halving_the_cell_size_changes_the_extrapolated_volumes_by_under_two_percent()
    {
        // Extrapolated volume at h = 2 V(h) - V(2h); compare h = 4 (from 8 and 4) with h = 2 (from 4 and 2).
        var robot = TestRobots.Crb;
        var v8 = WorkspaceCalculator.ComputeAt(robot, 8.0);
        var v4 = WorkspaceCalculator.ComputeAt(robot, 4.0);
        var v2 = WorkspaceCalculator.ComputeAt(robot, 2.0);

        AssertClose((2 * v2.ArmCm3) - v4.ArmCm3, (2 * v4.ArmCm3) - v8.ArmCm3, 0.02);
        AssertClose((2 * v2.UnionCm3) - v4.UnionCm3, (2 * v4.UnionCm3) - v8.UnionCm3, 0.02);
        AssertClose((2 * v2.SharedCm3) - v4.SharedCm3, (2 * v4.SharedCm3) - v8.SharedCm3, 0.03);

        // The raw volumes shrink towards the limit (whole marked cells over-cover the boundary).
        Assert.True(v2.ArmCm3 < v4.ArmCm3 && v4.ArmCm3 < v8.ArmCm3);
    }

    [Fact]
    public void Halving_the_cell_size_shrinks_the_raw_lb_volume_by_a_few_percent()
    {
        var robot = TestRobots.Lb;
        var coarse = WorkspaceCalculator.ComputeAt(robot, 8.0);
        var fine = WorkspaceCalculator.ComputeAt(robot, 4.0);

        Assert.True(fine.ArmCm3 < coarse.ArmCm3);
        Assert.InRange((coarse.ArmCm3 - fine.ArmCm3) / fine.ArmCm3, 0, 0.06);
    }

    [Fact]
    public void Volumes_are_consistent_between_the_two_grids_and_between_union_and_intersection()
    {
        var v = WorkspaceCalculator.ComputeAt(TestRobots.Crb, 4.0);

        Assert.InRange(Math.Abs(v.ArmCm3 - v.ArmCylindricalCm3) / v.ArmCylindricalCm3, 0, 0.01);
        Assert.True(v.SharedCm3 > 0 && v.SharedCm3 < v.ArmCm3);
        Assert.True(v.UnionCm3 > v.ArmCm3 && v.UnionCm3 < 2 * v.ArmCm3);

        // Both arms are mirror images (same volume), so union = 2 arm - shared up to the voxel noise of the mirrored arm.
        Assert.InRange(Math.Abs(v.UnionCm3 - ((2 * v.ArmCm3) - v.SharedCm3)) / v.UnionCm3, 0, 0.01);
    }

    [Fact]
    public void The_arm_volume_lies_inside_the_shell_its_link_lengths_allow()
    {
        // CRB: the tip lies between |L1 - L2 e^{i 75 deg}| and L1 + L2 from the shoulder centre.
        const double l1 = 68.58, l2 = 96.393;
        var inner = Math.Sqrt((l1 * l1) + (l2 * l2) - (2 * l1 * l2 * Math.Cos(75 * Math.PI / 180)));
        var shellCm3 = 4.0 / 3.0 * Math.PI * (Math.Pow(l1 + l2, 3) - Math.Pow(inner, 3)) / 1000;
        var v = WorkspaceCalculator.ComputeAt(TestRobots.Crb, 4.0);

        Assert.InRange(v.ArmCm3, 0.05 * shellCm3, shellCm3);
    }

    private static void AssertClose(double expected, double actual, double relative) =>
        Assert.InRange(Math.Abs(actual - expected) / expected, 0, relative);
}
