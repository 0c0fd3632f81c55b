using RobotControl.Bus.Transports.Serial;
using RobotControl.Host.Realtime;

namespace RobotControl.Host.Tests.Realtime;

/// <summary><c>doctor</c> on a made-up sysfs: an FTDI adapter at the default 16 ms latency timer, a powersave governor.</summary>
public sealed class DoctorTests : IDisposable
{
    private readonly DirectoryInfo _root = Directory.CreateTempSubdirectory("rcdoctor");

    public DoctorTests()
    {
        var sys = Path.Combine(_root.FullName, "sys");
        var device = Directory.CreateDirectory(Path.Combine(sys, "class", "tty", "ttyUSB9", "device")).FullName;
        File.WriteAllText(Path.Combine(device, "latency_timer"), "16\n");
        var driver = Directory.CreateDirectory(Path.Combine(sys, "bus", "usb-serial", "drivers", "ftdi_sio")).FullName;
        Directory.CreateSymbolicLink(Path.Combine(device, "driver"), driver);
        var cpufreq = Directory.CreateDirectory(Path.Combine(sys, "devices", "system", "cpu", "cpu0", "cpufreq")).FullName;
        File.WriteAllText(Path.Combine(cpufreq, "scaling_governor"), "powersave\n");
        File.WriteAllText(Tty, string.Empty); // the "device" node
    }

    private string Sys => Path.Combine(_root.FullName, "sys");

    private string ProcStat(long steal)
    {
        var path = Path.Combine(_root.FullName, $"stat-{steal}");
        File.WriteAllText(path, $"cpu  8000 0 1000 {1000 - steal} 0 0 0 {steal} 0 0\ncpu0 1 2 3 4 5 6 7 8\n");
        return path;
    }

    private string Tty => Path.Combine(_root.FullName, "ttyUSB9");

    public void Dispose() => _root.Delete(recursive: true);

    [Fact]
    public void Reports_the_latency_timer_the_baud_error_and_the_governor_with_what_to_change()
    {
        var findings = Doctor.Examine($"serial:{Tty}?baud=1000000", Sys).ToDictionary(f => f.Check);
        Assert.Contains("16 ms", findings["latency_timer"].Found, StringComparison.Ordinal);
        Assert.Contains("echo 1 >", findings["latency_timer"].Advice, StringComparison.Ordinal);
        Assert.Contains("runs at 1000000 (0 %)", findings["baud error"].Found, StringComparison.Ordinal);
        Assert.Null(findings["baud error"].Advice);
        Assert.Contains("powersave", findings["cpu frequency"].Found, StringComparison.Ordinal);
        Assert.Equal("cpupower frequency-set -g performance", findings["cpu frequency"].Advice);
        Assert.Contains("no serial_struct", findings["low_latency"].Found, StringComparison.Ordinal);
        Assert.True(findings.ContainsKey("real-time priority"));
    }

    [Fact]
    public void Opening_a_usb_serial_adapter_sets_its_latency_timer_to_1_ms()
    {
        Assert.Equal(16, LatencyTimer.Read(Tty, Sys));
        Assert.Equal(1, LatencyTimer.TrySetOneMs(Tty, Sys));
        Assert.Null(Doctor.Examine($"serial:{Tty}", Sys).Single(f => f.Check == "latency_timer").Advice);
        Assert.Null(LatencyTimer.TrySetOneMs("/dev/null", Sys)); // no latency timer: nothing to set
    }

    [Theory]
    [InlineData(1_000_000, 1_000_000, 0.0)]
    [InlineData(115_200, 115_384.6, 0.16)]
    [InlineData(921_600, 923_076.9, 0.16)]
    public void The_FTDI_baud_error_is_that_of_a_3_MHz_clock_divided_in_eighths(int baud, double actual, double errorPercent)
    {
        var (a, e) = Doctor.FtdiBaud(baud);
        Assert.Equal(actual, a, 0.1);
        Assert.Equal(errorPercent, e, 0.01);
    }

    [Fact]
    public void Steal_above_one_percent_of_cpu_time_gets_advice()
    {
        var stolen = Doctor.Examine($"serial:{Tty}", Sys, ProcStat(steal: 500)).Single(f => f.Check == "hypervisor steal");
        Assert.StartsWith("5.0 % of CPU time since boot (5 s)", stolen.Found, StringComparison.Ordinal);
        Assert.Contains("dedicated CPUs", stolen.Advice, StringComparison.Ordinal);

        var own = Doctor.Examine($"serial:{Tty}", Sys, ProcStat(steal: 0)).Single(f => f.Check == "hypervisor steal");
        Assert.Equal("0.0 % of CPU time since boot (0 s)", own.Found);
        Assert.Null(own.Advice);
    }

    [Fact]
    public void Wake_up_latency_over_a_fifth_of_the_period_at_p99_9_or_any_overflow_gets_advice()
    {
        static PlatformFloor Floor(double p999, long overflows = 0) => new(null, 10, new LatencyQuantiles(30, 80, p999, 900), overflows, 40);

        Assert.Null(Doctor.WakeUp(Floor(200), 80).Advice);
        Assert.Equal(
            "a SCHED_FIFO 80 thread woke p50/p99/p99.9/max 30/80/200/900 us late over 10 s (cyclictest; 40 ms stolen meanwhile)",
            Doctor.WakeUp(Floor(200), 80).Found);
        Assert.Contains("isolcpus=", Doctor.WakeUp(Floor(201), 80).Advice, StringComparison.Ordinal);
        Assert.NotNull(Doctor.WakeUp(Floor(100, overflows: 1), 80).Advice);
        Assert.Null(Doctor.Examine($"serial:{Tty}", Sys).SingleOrDefault(f => f.Check == "wake-up latency")); // only when asked
    }

    [Fact]
    public void A_missing_cyclictest_says_what_to_install()
    {
        var missing = Doctor.WakeUp(new PlatformFloor("cyclictest is not installed (apt-get install rt-tests)", 10, null, 0, 0), 80);
        Assert.Equal("apt-get install rt-tests", missing.Advice);
    }

    [Fact]
    public void Whether_runs_can_hold_the_cpus_wake_up_latency_is_reported_with_what_to_change_when_not()
    {
        var dir = Directory.CreateTempSubdirectory("rcqos").FullName;
        var writable = Path.Combine(dir, "cpu_dma_latency");
        File.WriteAllBytes(writable, [1, 0, 0, 0]);
        var held = Doctor.WakeLatencyHold(writable);
        Assert.Equal($"{writable} writable: real-time runs hold the CPUs' wake-up latency at 0 us", held.Found);
        Assert.Null(held.Advice);

        var missing = Doctor.WakeLatencyHold(Path.Combine(dir, "none", "cpu_dma_latency"));
        Assert.Contains("not held", missing.Found, StringComparison.Ordinal);
        Assert.Contains("udev rule", missing.Advice, StringComparison.Ordinal);
    }

    [Fact]
    public void A_missing_device_is_one_clear_error()
    {
        var ex = Assert.Throws<FormatException>(() => Doctor.Examine("serial:/dev/robotcontrol-none", Sys));
        Assert.Equal("--transport serial:/dev/robotcontrol-none: no device /dev/robotcontrol-none", ex.Message);
    }
}
