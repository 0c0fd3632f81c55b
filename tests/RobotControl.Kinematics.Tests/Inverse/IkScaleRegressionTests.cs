using System.Text.Json;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Kinematics.Tests.Inverse;

/// <summary>
/// Every target the solver failed when the benchmark ran it at scale (ScaleRegressionTargets.json: robot, target set,
/// bench seed and index, and the joints the target was made from) is solved now, from mid-range, by the default solver.
/// </summary>
public sealed class IkScaleRegressionTests
{
    private static readonly Lazy<List<Entry>> All = new(Load);

    public static TheoryData<string> Targets()
    {
        var data = new TheoryData<string>();
        foreach (var entry in All.Value)
        {
            data.Add(entry.Name);
        }

        return data;
    }

    [Fact]
    public void The_regression_file_holds_the_failures_found_at_scale_on_both_robots()
    {
        Assert.Contains(All.Value, e => e.Robot == "lb-1.0.json" && e.Set == "random");
        Assert.Contains(All.Value, e => e.Set == "near_singular");
        Assert.Contains(All.Value, e => e.Set == "at_limits");
        Assert.Contains(All.Value, e => e.Set == "near_boundary");
        Assert.All(All.Value, e => Assert.True(e.Seed > 0 && e.Index >= 0, e.Name));
    }

    [Theory]
    [MemberData(nameof(Targets))]
    public void A_target_failed_at_scale_is_solved(string name)
    {
        var entry = All.Value.Single(e => e.Name == name);
        var chain = new KinematicChain(TestRobots.ByFile(entry.Robot));
        Assert.True(chain.WithinLimits(entry.MadeFromRad, 1e-12), $"{name}: the joints it was made from are outside the limits");
        var target = IkTestData.TargetOf(chain, entry.MadeFromRad, Enum.Parse<OrientationAxes>(entry.Axes));
        var seed = new double[chain.JointCount];
        chain.MidRange(seed);
        var q = new double[chain.JointCount];

        var result = new IkSolver(chain).Solve(target, seed, q);

        Assert.True(result.Reached, $"{name}: {result}");
        Assert.False(result.AtCeiling);
        IkTestData.AssertReaches(chain, target, q);
    }

    private static List<Entry> Load()
    {
        var path = Path.Combine(AppContext.BaseDirectory, "Inverse", "ScaleRegressionTargets.json");
        using var document = JsonDocument.Parse(File.ReadAllText(path));
        return document.RootElement.GetProperty("targets").EnumerateArray()
            .Select(t => new Entry(
                t.GetProperty("robot").GetString()!,
                t.GetProperty("set").GetString()!,
                t.GetProperty("seed").GetUInt64(),
                t.GetProperty("index").GetInt32(),
                t.GetProperty("axes").GetString()!,
                t.GetProperty("made_from_rad").EnumerateArray().Select(v => v.GetDouble()).ToArray()))
            .ToList();
    }

    private sealed record Entry(string Robot, string Set, ulong Seed, int Index, string Axes, double[] MadeFromRad)
    {
        public string Name => $"{Robot} {Set} #{Index} (seed {Seed})";
    }
}
