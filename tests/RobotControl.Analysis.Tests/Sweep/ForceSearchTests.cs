using RobotControl.Analysis.Sweep;

namespace RobotControl.Analysis.Tests.Sweep;

public sealed class ForceSearchTests
{
    [Fact]
    public void Exact_search_equals_the_step_down_search_on_many_cases()
    {
        // A fixed-seed generator: the cases are reproducible.
        var random = new Random(12345);
        for (var n = 0; n < 20000; n++)
        {
            var count = 3 + (n % 3);
            var gains = new double[count];
            var limits = new double[count];
            for (var i = 0; i < count; i++)
            {
                gains[i] = (random.NextDouble() - 0.5) * 400 * Math.Pow(10, random.Next(-3, 2));
                limits[i] = random.NextDouble() * 4000;
            }

            if (n % 7 == 0)
            {
                gains[n % count] = 0;
            }

            Assert.Equal(ForceSearch.StepDown(gains, limits), ForceSearch.Largest(gains, limits));
        }
    }

    [Fact]
    public void Bounds_on_the_grid_are_kept_exactly()
    {
        for (var k = 1; k <= 300; k++)
        {
            var force = k / 10.0;
            double[] gains = [100, 0, 50];
            double[] limits = [100 * force, 1, 1e9];

            Assert.Equal(ForceSearch.StepDown(gains, limits), ForceSearch.Largest(gains, limits));
        }
    }

    [Fact]
    public void Force_is_capped_at_30_N_and_zero_when_nothing_holds()
    {
        Assert.Equal(30.0, ForceSearch.Largest([0, 0, 0], [1, 1, 1]));
        Assert.Equal(30.0, ForceSearch.Largest([1, 1, 1], [1000, 1000, 1000]));
        Assert.Equal(0.0, ForceSearch.Largest([1000, 1, 1], [1, 1000, 1000]));
        Assert.Equal(4.6, ForceSearch.Largest([165, 96.393], [3000, 448.1]));
    }
}
