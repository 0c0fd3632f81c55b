using RobotControl.Host.Realtime;

namespace RobotControl.Host.Tests.Realtime;

public sealed class CpuTimesTests
{
    [Fact]
    public void The_cpu_line_sums_eight_kinds_of_time_and_takes_steal_from_the_eighth()
    {
        // user nice system idle iowait irq softirq steal guest guest_nice (guest time is already in user and nice)
        var times = CpuTimes.Parse("cpu  3420141 1036623 558873 995247 9726 0 10345 464687 77 88");

        Assert.Equal(new CpuTimes(3420141 + 1036623 + 558873 + 995247 + 9726 + 0 + 10345 + 464687, 464687), times);
    }

    [Theory]
    [InlineData("cpu0 1 2 3 4 5 6 7 8")]
    [InlineData("intr 1 2 3 4 5")]
    [InlineData("cpu 1 2 x 4 5 6 7 8")]
    [InlineData("cpu 1 2")]
    public void Other_lines_are_not_cpu_times(string line) => Assert.Null(CpuTimes.Parse(line));

    [Fact]
    public void This_machine_has_cpu_times() => Assert.True(CpuTimes.Read()!.Total > 0);
}
