using RobotControl.Host.Realtime;

namespace RobotControl.Host.Tests.Realtime;

/// <summary>The PM QoS request: a 32-bit 0 written and the file kept open while held; a missing device said in one line.</summary>
public sealed class CpuLatencyHoldTests
{
    [Fact]
    public void A_request_writes_a_32_bit_zero_and_holds_the_file_open_until_disposed()
    {
        var device = Path.Combine(Directory.CreateTempSubdirectory("rcqos").FullName, "cpu_dma_latency");
        File.WriteAllBytes(device, [0xFF, 0xFF, 0xFF, 0xFF]);
        using (var hold = CpuLatencyHold.Request(device))
        {
            Assert.True(hold.Held, hold.Outcome);
            Assert.Equal($"CPU wake-up latency held at 0 us ({device})", hold.Outcome);
            Assert.Equal(new byte[] { 0, 0, 0, 0 }, File.ReadAllBytes(device));
            using var handle = new FileStream(device, FileMode.Open, FileAccess.Read, FileShare.ReadWrite);
            Assert.True(handle.CanRead); // shared: the kernel's device takes any number of requests
        }
    }

    [Fact]
    public void A_machine_without_the_device_is_told_in_one_line_and_nothing_is_held()
    {
        var device = Path.Combine(Directory.CreateTempSubdirectory("rcqos").FullName, "missing", "cpu_dma_latency");
        using var hold = CpuLatencyHold.Request(device);
        Assert.False(hold.Held);
        Assert.Equal($"CPU wake-up latency not held: {device}: the kernel has no PM QoS device; idle CPUs may wake late", hold.Outcome);
    }

    [Fact]
    public void Real_time_threads_hold_the_latency_unless_a_benchmark_asks_them_not_to()
    {
        Assert.True(new RealtimeThreads(80, null).HoldCpuLatency);
        Assert.False(new RealtimeThreads(80, null) { HoldCpuLatency = false }.HoldCpuLatency);
    }
}
