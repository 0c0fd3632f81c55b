using System.Diagnostics;
using RobotControl.Simulation.Tests.Support;

using RobotControl.TestSupport;

namespace RobotControl.Simulation.Tests.EndToEnd;

/// <summary>
/// Interoperability with a master written independently from the published Dynamixel Protocol 2.0
/// (tests/interop/dxl_master.py, Python standard library only): it drives the virtual robot over a pty and checks every
/// instruction, every error code and that nothing is silently dropped.
/// </summary>
public sealed class PythonInteropTests
{
    [Fact]
    public async Task The_independent_master_finds_every_instruction_and_error_code_as_the_protocol_defines_them()
    {
        using var served = new ServedPty();
        var script = Path.Combine(RepositoryPaths.Root, "tests", "interop", "dxl_master.py");
        var start = new ProcessStartInfo("python3", $"\"{script}\" {served.SlavePath}") { RedirectStandardOutput = true, RedirectStandardError = true };
        using var master = Process.Start(start)!;
        var output = master.StandardOutput.ReadToEndAsync();
        var errors = master.StandardError.ReadToEndAsync();
        using var timeout = new CancellationTokenSource(TimeSpan.FromSeconds(60));
        await master.WaitForExitAsync(timeout.Token);
        var text = await output + await errors;
        Assert.True(master.ExitCode == 0, text);
        Assert.DoesNotContain("FAIL", text, StringComparison.Ordinal);
        Assert.Contains("ok   fast bulk read: one packet, each part with its CRC", text, StringComparison.Ordinal);
        Assert.Contains("ok   bulk write applied (second module)", text, StringComparison.Ordinal);
        Assert.Contains("ok   sync write applied (second module)", text, StringComparison.Ordinal);
        Assert.Contains("ok   broadcast action applied (second module)", text, StringComparison.Ordinal);
        Assert.Contains("ok   reply data FF FF FD FF comes stuffed (FF FF FD FD FF)", text, StringComparison.Ordinal);
        Assert.Contains("ok   alert bit set once the watchdog expired", text, StringComparison.Ordinal);
        Assert.Contains("ok   after the factory reset: kp back at its default 256, same ID and baud", text, StringComparison.Ordinal);
    }
}
