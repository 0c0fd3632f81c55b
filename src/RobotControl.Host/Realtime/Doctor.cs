using System.Globalization;
using RobotControl.Bus.Transports;
using RobotControl.Bus.Transports.Serial;

namespace RobotControl.Host.Realtime;

/// <summary>One finding of <see cref="Doctor"/>: what was checked, what was found, and what to change (null: fine).</summary>
/// <param name="Check">What was checked.</param>
/// <param name="Found">What was found.</param>
/// <param name="Advice">What to change (null: nothing).</param>
public sealed record DoctorFinding(string Check, string Found, string? Advice);

/// <summary>
/// Checks what the real-time path depends on, for a transport: the port's latency timer and low-latency flag, its
/// baud error (FTDI chips: a 3 MHz clock divided in eighths), the real-time priority this process may have, the CPU
/// frequency scaling governor, the CPU time a hypervisor steals and, when asked, how late this machine wakes a
/// SCHED_FIFO thread (<see cref="PlatformFloor"/>); and says what to change.
/// </summary>
public static class Doctor
{
    private const double FtdiClockHz = 3_000_000;

    /// <summary>Wake-up latency (p99.9) above which the 1 kHz loop cannot keep its ticks: a fifth of its period.</summary>
    public const double WakeUpP999LimitUs = 200;

    /// <summary>Share of CPU time stolen by a hypervisor above which the machine stalls for milliseconds at a time.</summary>
    public const double StealLimitPercent = 1;

    /// <summary>
    /// The findings for <paramref name="transport"/> (paths under <paramref name="sysRoot"/>, CPU times from
    /// <paramref name="procStat"/>). With <paramref name="latencyProbe"/> &gt; 0, cyclictest runs that long at
    /// SCHED_FIFO <paramref name="probePriority"/>.
    /// </summary>
    /// <exception cref="FormatException">The transport is malformed or its device missing.</exception>
    public static IReadOnlyList<DoctorFinding> Examine(string transport, string sysRoot = "/sys", string procStat = "/proc/stat", TimeSpan latencyProbe = default, int probePriority = 80)
    {
        var uri = Session.TransportOverride.Check(transport);
        var findings = new List<DoctorFinding>();
        if (uri.Kind is LinkKind.Serial or LinkKind.Usb)
        {
            var device = uri.Kind == LinkKind.Serial ? uri.Target : ResolveUsb(uri);
            Port(device, uri.BaudRate, sysRoot, findings);
        }
        else
        {
            findings.Add(new DoctorFinding("port", $"{uri.Kind.ToString().ToLowerInvariant()} transport: no serial port to check", null));
        }

        findings.Add(Priority());
        findings.Add(Governor(sysRoot));
        findings.Add(WakeLatencyHold(CpuLatencyHold.Device));
        findings.Add(Steal(procStat));
        if (latencyProbe > TimeSpan.Zero)
        {
            findings.Add(WakeUp(PlatformFloor.Measure(latencyProbe, probePriority), probePriority));
        }

        return findings;
    }

    /// <summary>The finding for a measured <paramref name="floor"/> (cyclictest at <paramref name="priority"/>).</summary>
    public static DoctorFinding WakeUp(PlatformFloor floor, int priority)
    {
        ArgumentNullException.ThrowIfNull(floor);
        if (floor.WakeUpLatencyUs is not { } w)
        {
            return new DoctorFinding("wake-up latency", floor.Problem ?? "not measured", floor.Problem?.Contains("not installed", StringComparison.Ordinal) == true ? "apt-get install rt-tests" : null);
        }

        var found = string.Create(CultureInfo.InvariantCulture, $"a SCHED_FIFO {priority} thread woke p50/p99/p99.9/max {w.P50:F0}/{w.P99:F0}/{w.P999:F0}/{w.Max:F0} us late over {floor.Seconds:F0} s (cyclictest; {floor.StealMs:F0} ms stolen meanwhile)");
        return w.P999 <= WakeUpP999LimitUs && floor.Overflows == 0
            ? new DoctorFinding("wake-up latency", found, null)
            : new DoctorFinding("wake-up latency", found + ": the 1 kHz loop will start ticks that late", "use CPUs of its own: bare metal or pinned, isolated vCPUs (isolcpus=, then --cpu), a PREEMPT_RT kernel, no other load at real-time priority");
    }

    private static DoctorFinding Steal(string procStat)
    {
        if (CpuTimes.Read(procStat) is not { Total: > 0 } times)
        {
            return new DoctorFinding("hypervisor steal", $"{procStat}: no CPU times to read", null);
        }

        var percent = 100.0 * times.Steal / times.Total;
        var found = string.Create(CultureInfo.InvariantCulture, $"{percent:F1} % of CPU time since boot ({times.Steal * CpuTimes.MillisecondsPerTick / 1000:F0} s)");
        return percent <= StealLimitPercent
            ? new DoctorFinding("hypervisor steal", found, null)
            : new DoctorFinding("hypervisor steal", found + ": the host runs something else on these CPUs, and a loop waits milliseconds for them", "run on dedicated CPUs (bare metal, or a virtual machine with pinned vCPUs); check with robotctl doctor --latency 10s");
    }

    /// <summary>The baud rate an FTDI chip makes of <paramref name="baud"/> (3 MHz / divisor in 1/8 steps), and the error in %.</summary>
    public static (double ActualBaud, double ErrorPercent) FtdiBaud(int baud)
    {
        ArgumentOutOfRangeException.ThrowIfNegativeOrZero(baud);
        var eighths = Math.Max(8, Math.Round(FtdiClockHz * 8 / baud));
        var actual = FtdiClockHz * 8 / eighths;
        return (actual, (actual - baud) / baud * 100);
    }

    private static string ResolveUsb(LinkUri uri)
    {
        var (vendor, product, serial) = uri.UsbIds();
        return UsbSerialResolver.Resolve(vendor, product, serial);
    }

    private static void Port(string device, int baud, string sysRoot, List<DoctorFinding> findings)
    {
        var c = CultureInfo.InvariantCulture;
        var latency = LatencyTimer.Read(device, sysRoot);
        findings.Add(latency switch
        {
            null => new DoctorFinding("latency_timer", $"{device}: none (not a USB-serial adapter with one)", null),
            1 => new DoctorFinding("latency_timer", $"{device}: 1 ms", null),
            _ => new DoctorFinding("latency_timer", string.Create(c, $"{device}: {latency} ms: every reply waits up to that long in the adapter"), $"echo 1 > {LatencyTimer.File(device, sysRoot)} (robotctl does this when it may write it; a udev rule makes it permanent)"),
        });

        var flags = DoctorCalls.SerialFlags(device);
        findings.Add(flags switch
        {
            null => new DoctorFinding("low_latency", $"{device}: no serial_struct (a pseudo-terminal, or a driver without it)", null),
            _ when (flags & DoctorCalls.AsyncLowLatency) != 0 => new DoctorFinding("low_latency", $"{device}: set", null),
            _ => new DoctorFinding("low_latency", $"{device}: not set", $"setserial {device} low_latency"),
        });

        var driver = Path.Combine(sysRoot, "class", "tty", Path.GetFileName(device), "device", "driver");
        var isFtdi = Directory.Exists(driver) && (new DirectoryInfo(driver).ResolveLinkTarget(true)?.Name ?? string.Empty).Contains("ftdi", StringComparison.Ordinal);
        if (isFtdi)
        {
            var (actual, error) = FtdiBaud(baud);
            findings.Add(new DoctorFinding("baud error", string.Create(c, $"{baud} baud on an FTDI chip runs at {actual:F0} ({error:+0.00;-0.00;0} %)"), Math.Abs(error) > 1.5 ? "pick a baud rate 3 MHz divides closely (1000000, 3000000, 2000000, 500000)" : null));
        }
        else
        {
            findings.Add(new DoctorFinding("baud error", string.Create(c, $"{baud} baud: the chip behind {device} is not an FTDI one; its error is not computed"), null));
        }
    }

    private static DoctorFinding Priority()
    {
        var threads = new RealtimeThreads(priority: 99, cpu: null);
        threads.Probe();
        return threads.GotRealtimePriority
            ? new DoctorFinding("real-time priority", $"this process may use {threads.Outcome}", null)
            : new DoctorFinding("real-time priority", threads.Outcome, "grant CAP_SYS_NICE (setcap cap_sys_nice+ep) or an rtprio limit, then run with --rt-priority 80");
    }

    /// <summary>Whether a run can hold the CPUs' wake-up latency at 0 us (<see cref="CpuLatencyHold"/>): tried here and let go at once.</summary>
    public static DoctorFinding WakeLatencyHold(string device)
    {
        using var hold = CpuLatencyHold.Request(device);
        return hold.Held
            ? new DoctorFinding("cpu idle states", $"{device} writable: real-time runs hold the CPUs' wake-up latency at 0 us", null)
            : new DoctorFinding("cpu idle states", hold.Outcome, $"run as root, or give the operators' group write access to {device} with a udev rule");
    }

    private static DoctorFinding Governor(string sysRoot)
    {
        var cpus = Path.Combine(sysRoot, "devices", "system", "cpu");
        var governors = Directory.Exists(cpus)
            ? Directory.GetDirectories(cpus, "cpu*")
                .Select(d => Path.Combine(d, "cpufreq", "scaling_governor"))
                .Where(File.Exists)
                .Select(f => File.ReadAllText(f).Trim())
                .Distinct(StringComparer.Ordinal)
                .ToList()
            : [];
        if (governors.Count == 0)
        {
            return new DoctorFinding("cpu frequency", "no cpufreq scaling here (fixed clock, or a virtual machine)", null);
        }

        var found = string.Join(", ", governors);
        return governors.All(g => g == "performance")
            ? new DoctorFinding("cpu frequency", $"governor {found}", null)
            : new DoctorFinding("cpu frequency", $"governor {found}: the clock drops between bursts and wakes late", "cpupower frequency-set -g performance");
    }
}
