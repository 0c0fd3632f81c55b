using RobotControl.Host.Realtime;

namespace RobotControl.Host.Tests.Realtime;

/// <summary>The machine's own floor: cyclictest's histogram read into quantiles, and a real one-second measurement.</summary>
public sealed class PlatformFloorTests
{
    // As cyclictest -q -h prints it (1 us buckets, zero buckets left out here), for 1,000 wake-ups and 2 overflows.
    private const string Histogram = """
        # /dev/cpu_dma_latency set to 0us
        # Histogram
        000020 000400
        000021 000495
        000150 000100
        000900 000003
        # Total: 000001000
        # Min Latencies: 00020
        # Avg Latencies: 00035
        # Max Latencies: 12000
        # Histogram Overflows: 00002
        # Histogram Overflow at cycle number:
        # Thread 0: 00017 00512
        """;

    [Fact]
    public void Quantiles_count_the_overflows_as_later_than_every_bucket()
    {
        var (latency, overflows) = PlatformFloor.Parse(Histogram);

        // 998 in the buckets and 2 overflows: ranks 500 (p50), 990 (p99) and 999 (p99.9: the first overflow).
        Assert.Equal(2, overflows);
        Assert.Equal(new LatencyQuantiles(21, 150, PlatformFloor.HistogramUs, 12000), latency);
    }

    [Fact]
    public void Output_without_a_histogram_gives_nothing()
    {
        Assert.Equal((null, 0), PlatformFloor.Parse("# /dev/cpu_dma_latency set to 0us\n"));
    }

    [Fact]
    public void A_second_of_cyclictest_on_this_machine_gives_about_a_thousand_wake_ups()
    {
        // rt-tests is installed by tools/bootstrap.sh; priority 1 is the lowest SCHED_FIFO one.
        var floor = PlatformFloor.Measure(TimeSpan.FromSeconds(1), priority: 1);

        Assert.Null(floor.Problem);
        Assert.Equal(1, floor.Seconds);
        var w = floor.WakeUpLatencyUs!;
        Assert.True(w.P50 <= w.P99 && w.P99 <= w.P999 && w.P999 <= Math.Max(w.Max, PlatformFloor.HistogramUs), $"{w}");
        Assert.True(w.P50 > 0, $"{w}");
        Assert.True(floor.StealMs >= 0);
    }
}
