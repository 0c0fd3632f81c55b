using System.CommandLine;
using System.Diagnostics;
using RobotControl.Cli.Commands.Devices;
using RobotControl.Tests.FakeHd;

namespace RobotControl.Cli.Tests.Commands.Devices;

[Collection(FakeHdCollection.Name)]
public sealed class DevicesCommandTests
{
    public DevicesCommandTests() => FakeHdLibrary.Reset();

    [Fact]
    public void Lists_the_devices_it_can_open_with_serial_calibration_and_nominal_forces()
    {
        FakeHdLibrary.SetCalibration("left", FakeHdLibrary.CalibrationNeedsManualInput);

        var (code, output, error) = Invoke("devices", "--device", "right", "--device", "left", "--device", "nowhere", "--library-path", FakeHdLibrary.Folder);

        Assert.True(code == 0, error);
        var lines = output.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);
        Assert.Equal(
            [
                $"OpenHaptics library: {Path.Combine(FakeHdLibrary.Folder, "libHD.so")}",
                "right: Touch (fake), serial FAKE-0001, calibration ok, nominal max force 3.3 N, continuous 0.88 N",
                "left: Touch (fake), serial FAKE-0002, calibration needs manual input (run Touch Setup / Touch Diagnostic), nominal max force 3.3 N, continuous 0.88 N",
                "nowhere: cannot open: fake: no such device configured (HD error 0x0303, internal -1)",
                "2 of 3 device(s) opened",
            ],
            lines);
        Assert.False(FakeHdLibrary.IsOpen("right"));
    }

    [Fact]
    public void Without_a_device_that_opens_it_exits_non_zero()
    {
        FakeHdLibrary.FailInit("right");

        var (code, output, _) = Invoke("devices", "--library-path", FakeHdLibrary.Folder);

        Assert.Equal(1, code);
        Assert.Contains("(default device): cannot open: fake: device fault", output, StringComparison.Ordinal);
    }

    [Fact]
    public void Without_the_library_it_says_what_to_install_and_exits_non_zero()
    {
        var empty = Directory.CreateTempSubdirectory("rc-no-hd-").FullName;
        try
        {
            // A process of its own: this one may already have the fake library loaded.
            var (code, output, error) = Robotctl(new Dictionary<string, string> { ["LD_LIBRARY_PATH"] = empty }, "devices");

            Assert.Equal(2, code);
            Assert.Equal("", output);
            var line = Assert.Single(error.Split('\n', StringSplitOptions.RemoveEmptyEntries));
            Assert.StartsWith($"OpenHaptics library libHD.so not found (tried {Path.Combine(empty, "libHD.so")}, libHD.so): install OpenHaptics", line, StringComparison.Ordinal);
        }
        finally
        {
            Directory.Delete(empty, true);
        }
    }

    /// <summary>Runs robotctl in a process of its own (its output folder is this test's).</summary>
    internal static (int Code, string Output, string Error) Robotctl(IReadOnlyDictionary<string, string> environment, params string[] args)
    {
        var start = new ProcessStartInfo(Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") ?? "dotnet")
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
        };
        start.ArgumentList.Add(Path.Combine(AppContext.BaseDirectory, "robotctl.dll"));
        foreach (var a in args)
        {
            start.ArgumentList.Add(a);
        }

        foreach (var (key, value) in environment)
        {
            start.Environment[key] = value;
        }

        using var process = Process.Start(start)!;
        var output = process.StandardOutput.ReadToEndAsync();
        var error = process.StandardError.ReadToEnd();
        process.WaitForExit();
        return (process.ExitCode, output.Result, error);
    }

    private static (int Code, string Output, string Error) Invoke(params string[] args)
    {
        var root = new RootCommand { new DevicesCommand().Build() };
        var output = new StringWriter();
        var error = new StringWriter();
        var code = root.Parse(args).Invoke(new InvocationConfiguration { Output = output, Error = error });
        return (code, output.ToString(), error.ToString());
    }
}
