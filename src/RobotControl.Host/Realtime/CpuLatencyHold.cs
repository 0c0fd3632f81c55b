namespace RobotControl.Host.Realtime;

/// <summary>
/// Holds the CPUs' wake-up latency at 0 us for as long as it is open: Linux's PM QoS request through
/// <c>/dev/cpu_dma_latency</c> (write the latency as a 32-bit integer, keep the file open; closing it drops the
/// request). Idle CPUs then stay out of deep idle states, from which a timer wake-up of the loop or the bus thread
/// comes late. This is what cyclictest does for its own measurement; on this project's 2-vCPU virtual machine the
/// loop's tick start jitter p99.9 fell from milliseconds to about 0.1 ms with it (docs/perf/realtime.md).
/// Writing the file needs root (or a udev rule giving the group write access); without it, <see cref="Outcome"/> says
/// so and the run goes on.
/// </summary>
public sealed class CpuLatencyHold : IDisposable
{
    /// <summary>The PM QoS device.</summary>
    public const string Device = "/dev/cpu_dma_latency";

    private readonly FileStream? _request;

    private CpuLatencyHold(FileStream? request, string outcome)
    {
        _request = request;
        Outcome = outcome;
    }

    /// <summary>What was held, or why not, in one line.</summary>
    public string Outcome { get; }

    /// <summary>True while the request is held.</summary>
    public bool Held => _request is not null;

    /// <summary>Asks for 0 us wake-up latency; the request holds until <see cref="Dispose"/>.</summary>
    public static CpuLatencyHold Request() => Request(Device);

    /// <summary>As <see cref="Request()"/>, through <paramref name="device"/> (tests give a file of their own).</summary>
    public static CpuLatencyHold Request(string device)
    {
        ArgumentException.ThrowIfNullOrEmpty(device);
        if (!OperatingSystem.IsLinux())
        {
            return new CpuLatencyHold(null, "CPU wake-up latency not held (Linux only)");
        }

        FileStream? stream = null;
        try
        {
            stream = new FileStream(device, FileMode.Open, FileAccess.Write, FileShare.ReadWrite, bufferSize: 0);
            stream.Write(BitConverter.GetBytes(0)); // s32, in microseconds
            stream.Flush();
            return new CpuLatencyHold(stream, $"CPU wake-up latency held at 0 us ({device})");
        }
        catch (Exception ex) when (ex is UnauthorizedAccessException or IOException)
        {
            stream?.Dispose();
            var why = ex switch
            {
                UnauthorizedAccessException => "no permission to write it (root, or a udev rule for the group)",
                FileNotFoundException or DirectoryNotFoundException => "the kernel has no PM QoS device",
                _ => ex.Message,
            };
            return new CpuLatencyHold(null, $"CPU wake-up latency not held: {device}: {why}; idle CPUs may wake late");
        }
    }

    /// <inheritdoc />
    public void Dispose() => _request?.Dispose();
}
