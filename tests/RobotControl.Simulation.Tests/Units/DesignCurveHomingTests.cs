using RobotControl.Simulation;
using RobotControl.TestSupport;
using Xunit.Abstractions;

namespace RobotControl.Simulation.Tests.Units;

/// <summary>
/// Homing from the pots with the robot file's design curves, on a unit whose pots differ (unit variation): the
/// joints come out off by a measurable amount (why a unit's pots are calibrated), while on a unit built exactly to
/// the design they agree.
/// </summary>
public sealed class DesignCurveHomingTests(ITestOutputHelper output)
{
    private const double Deg = Math.PI / 180;

    [Fact]
    public void Homing_with_the_design_curves_is_off_on_a_varied_unit_and_right_on_the_design()
    {
        var design = WorstJointErrorDeg(unitSeed: null);
        var varied = new[] { 1, 2, 3 }.Select(seed => (Seed: seed, Error: WorstJointErrorDeg(seed))).ToList();
        output.WriteLine($"design unit: worst joint error after homing {design.Deg:F2} deg ({design.Where})");
        foreach (var (seed, error) in varied)
        {
            output.WriteLine($"unit variation seed {seed}: worst joint error after homing with the design curves {error.Deg:F2} deg ({error.Where})");
        }

        Assert.True(design.Deg < 0.5, $"the design unit homed {design.Deg:F2} deg off at {design.Where}");
        Assert.All(varied, v => Assert.True(v.Error.Deg > 1.0, $"seed {v.Seed}: homing with the design curves was only {v.Error.Deg:F2} deg off"));
    }

    private static (double Deg, string Where) WorstJointErrorDeg(int? unitSeed)
    {
        var lb = VirtualLb.Lb;
        // A pose away from mid-range on every joint, the same on both arms.
        var pose = lb.Joints.Select(j => j.MinRad + (0.3 * (j.MaxRad - j.MinRad))).ToArray();
        var options = new VirtualRobotOptions { UnitVariationSeed = unitSeed, InitialJointsRad = [pose, pose], PotNoiseCounts = 0 };
        using var unit = new VirtualLb(options, start: false);
        unit.Robot.Discover();
        var homing = unit.Robot.Home();
        Assert.All(homing, h => Assert.True(h.Succeeded, h.ToString()));
        unit.Robot.RunFor(TimeSpan.FromMilliseconds(20));
        var worst = (Deg: 0.0, Where: "");
        Span<double> q = stackalloc double[lb.JointCount];
        for (var arm = 0; arm < lb.Arms.Count; arm++)
        {
            unit.Robot.ReadJointPositions(arm, q);
            for (var j = 0; j < q.Length; j++)
            {
                var error = Math.Abs(q[j] - pose[j]) / Deg;
                if (error > worst.Deg)
                {
                    worst = (error, $"{lb.Arms[arm].Name}.{lb.Joints[j].Name}");
                }
            }
        }

        return worst;
    }
}
