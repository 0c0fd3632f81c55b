using System.Diagnostics;
using System.Text.RegularExpressions;
using RobotControl.Bus.Protocol;
using RobotControl.Cli.Tests.Commands.Run;

namespace RobotControl.Cli.Tests.Commands.Bus;

/// <summary>
/// <c>firmware/flash.sh</c>'s last step, reading the firmware version back over the bus with <c>robotctl discover</c>,
/// against a fresh module: <c>bus-sim --factory --connected 1</c> in its own process behind a pty (the real firmware),
/// after an OpenOCD stand-in that reports a verified programming (no probe exists here; test_flash.sh covers the
/// OpenOCD side).
/// </summary>
[Collection(RunProcess.Collection)]
[System.Runtime.Versioning.SupportedOSPlatform("linux")]
public sealed partial class FlashReadBackTests
{
    [Fact]
    public void After_flashing_the_fresh_module_answers_at_the_default_id_with_the_images_firmware_version()
    {
        using var sim = new RunProcess("bus-sim", Cli.RepoFile("hardware/robots/lb-1.0.json"), "--pty", "--factory", "--connected", "1");
        var transport = Transport().Match(sim.WaitFor("plug modules in on stdin", RunProcess.Patience)).Value;
        var dir = Directory.CreateTempSubdirectory("flash");
        try
        {
            var openocd = Path.Combine(dir.FullName, "openocd");
            File.WriteAllText(openocd, "#!/bin/sh\necho '** Programming Finished **'\necho '** Verified OK **'\necho '** Resetting Target **'\n");
            File.SetUnixFileMode(openocd, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute);
            var image = Path.Combine(dir.FullName, "rcfw_kv11z.elf");
            File.WriteAllText(image, "");

            var (code, output) = Flash("--image", image, "--openocd", openocd, "--robotctl", $"dotnet {Path.Combine(AppContext.BaseDirectory, "robotctl.dll")}", "--transport", transport);

            var table = ControlTable.Firmware;
            Assert.True(code == 0, output);
            Assert.Contains($"module {(int)table["id"].Default} answers with firmware {(int)table["firmware_version"].Default} on {transport}", output, StringComparison.Ordinal);
        }
        finally
        {
            dir.Delete(recursive: true);
        }
    }

    private static (int Code, string Output) Flash(params string[] args)
    {
        var start = new ProcessStartInfo("bash") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        start.ArgumentList.Add(Cli.RepoFile("firmware/flash.sh"));
        foreach (var a in args)
        {
            start.ArgumentList.Add(a);
        }

        using var process = Process.Start(start)!;
        var error = process.StandardError.ReadToEndAsync();
        var output = process.StandardOutput.ReadToEnd();
        Assert.True(process.WaitForExit(RunProcess.Patience), "flash.sh did not finish");
        return (process.ExitCode, output + error.Result);
    }

    [GeneratedRegex(@"serial:\S+")]
    private static partial Regex Transport();
}
