using RobotControl.Plugins.Sdk.Sampling;

namespace RobotControl.Plugins.Sdk.Tests.Sampling;

public sealed class SampleTimesTests
{
    private static readonly double[] Times = [0.0, 0.5, 1.0, 2.0];

    [Theory]
    [InlineData(-1.0, 0)]
    [InlineData(0.0, 0)]
    [InlineData(0.49, 0)]
    [InlineData(0.5, 1)]
    [InlineData(1.99, 2)]
    [InlineData(2.0, 3)]
    [InlineData(9.0, 3)]
    public void Finds_the_last_sample_at_or_before_the_time(double t, int expected)
    {
        var hint = 0;
        Assert.Equal(expected, SampleTimes.IndexAtOrBefore(Times, t, ref hint));
        Assert.Equal(expected, hint);
    }

    [Fact]
    public void Walks_forward_from_the_hint_and_restarts_when_time_goes_back()
    {
        var hint = 0;
        Assert.Equal(2, SampleTimes.IndexAtOrBefore(Times, 1.5, ref hint));
        Assert.Equal(3, SampleTimes.IndexAtOrBefore(Times, 2.5, ref hint));
        Assert.Equal(1, SampleTimes.IndexAtOrBefore(Times, 0.7, ref hint));

        var stale = 99;
        Assert.Equal(2, SampleTimes.IndexAtOrBefore(Times, 1.2, ref stale));
        stale = -5;
        Assert.Equal(2, SampleTimes.IndexAtOrBefore(Times, 1.2, ref stale));
    }

    [Fact]
    public void No_sample_times_is_an_argument_error()
    {
        var hint = 0;
        Assert.Throws<ArgumentException>(() => SampleTimes.IndexAtOrBefore([], 0.0, ref hint));
    }
}
