using System.Diagnostics;
using System.Runtime.InteropServices;

namespace RobotControl.Tests.FakeHd;

/// <summary>The fake libHD is one per process: its tests run one at a time.</summary>
[CollectionDefinition(Name, DisableParallelization = true)]
public sealed class FakeHdCollection
{
    public const string Name = "fake libHD";
}

/// <summary>
/// The fake OpenHaptics library (tests/FakeHd/fakehd.c): built with CMake into the test's output folder on first use,
/// loaded by path, and driven through its fakehd_* exports. Process-wide state: tests using it share a collection.
/// </summary>
internal static unsafe class FakeHdLibrary
{
    private static readonly Lazy<string> Built = new(Build);
    private static readonly Dictionary<string, nint> Names = [];
    private static nint _handle;

    /// <summary>The folder holding the built libHD.so (what a Touch's library_path or LD_LIBRARY_PATH names).</summary>
    public static string Folder => Built.Value;

    /// <summary>HD_CALIBRATION_NEEDS_MANUAL_INPUT, for <see cref="SetCalibration"/>.</summary>
    public const uint CalibrationNeedsManualInput = 0x5002;

    /// <summary>HD_COMM_ERROR.</summary>
    public const uint CommError = 0x0302;

    /// <summary>HD_EXCEEDED_MAX_FORCE.</summary>
    public const uint ExceededMaxForce = 0x0201;

    /// <summary>Stops the fake's scheduler and restores its default devices (right, left) at rest.</summary>
    public static void Reset() => ((delegate* unmanaged<void>)Export("fakehd_reset"))();

    /// <summary>A keyframe from the device's frame <paramref name="frame"/> on: translation (mm), yaw about z (rad), buttons.</summary>
    public static void Key(string device, long frame, double x, double y, double z, double yaw = 0, int buttons = 0)
    {
        var (c, s) = (Math.Cos(yaw), Math.Sin(yaw));
        double[] m = [c, s, 0, 0, -s, c, 0, 0, 0, 0, 1, 0, x, y, z, 1];
        double[] joints = [0.1, 0.2, 0.3];
        double[] gimbal = [0.4, 0.5, 0.6];
        fixed (double* pm = m, pj = joints, pg = gimbal)
        {
            Check(((delegate* unmanaged<byte*, long, double*, double*, double*, int, int>)Export("fakehd_script_key"))(Utf8(device), frame, pm, pj, pg, buttons));
        }
    }

    public static void FailInit(string device) => Check(((delegate* unmanaged<byte*, int, int>)Export("fakehd_fail_init"))(Utf8(device), 1));

    public static void SetCalibration(string device, uint state) => Check(((delegate* unmanaged<byte*, uint, int>)Export("fakehd_set_calibration"))(Utf8(device), state));

    public static void SetLimits(string device, double peak, double continuous) => Check(((delegate* unmanaged<byte*, double, double, int>)Export("fakehd_set_limits"))(Utf8(device), peak, continuous));

    /// <summary>From <paramref name="frame"/> the device reports <paramref name="code"/> (every frame, readings frozen, when <paramref name="persistent"/>: unplugged).</summary>
    public static void FailAt(string device, long frame, uint code, bool persistent) =>
        Check(((delegate* unmanaged<byte*, long, uint, int, int, int>)Export("fakehd_fail_at"))(Utf8(device), frame, code, 7, persistent ? 1 : 0));

    public static long Frames(string device) => ((delegate* unmanaged<byte*, long>)Export("fakehd_frames"))(Utf8(device));

    public static bool ForceOutputEverEnabled(string device) => ((delegate* unmanaged<byte*, int>)Export("fakehd_force_output_ever_enabled"))(Utf8(device)) == 1;

    public static bool IsOpen(string device) => ((delegate* unmanaged<byte*, int>)Export("fakehd_is_initialised"))(Utf8(device)) == 1;

    public static bool SchedulerRunning => ((delegate* unmanaged<int>)Export("fakehd_scheduler_running"))() == 1;

    /// <summary>Every force the device was given: frame, force (N) and whether force output was enabled.</summary>
    public static IReadOnlyList<(long Frame, double X, double Y, double Z, bool Enabled)> Forces(string device)
    {
        var count = ((delegate* unmanaged<byte*, long>)Export("fakehd_force_count"))(Utf8(device));
        var buffer = new double[Math.Max(1, count) * 5];
        long copied;
        fixed (double* p = buffer)
        {
            copied = ((delegate* unmanaged<byte*, long, double*, long, long>)Export("fakehd_forces"))(Utf8(device), 0, p, count);
        }

        return [.. Enumerable.Range(0, (int)copied).Select(i => ((long)buffer[i * 5], buffer[(i * 5) + 1], buffer[(i * 5) + 2], buffer[(i * 5) + 3], buffer[(i * 5) + 4] != 0))];
    }

    private static void Check(int result)
    {
        if (result != 0)
        {
            throw new InvalidOperationException($"fake libHD refused the call ({result})");
        }
    }

    private static byte* Utf8(string text)
    {
        // Device names are few and short: keep each one for the life of the process.
        lock (Names)
        {
            if (!Names.TryGetValue(text, out var p))
            {
                p = Marshal.StringToCoTaskMemUTF8(text);
                Names[text] = p;
            }

            return (byte*)p;
        }
    }

    private static nint Export(string name)
    {
        if (_handle == 0)
        {
            _handle = NativeLibrary.Load(Path.Combine(Folder, "libHD.so"));
        }

        return NativeLibrary.GetExport(_handle, name);
    }

    private static string Build()
    {
        var source = Path.Combine(RepoRoot(), "tests", "FakeHd");
        var build = Path.Combine(AppContext.BaseDirectory, "fakehd-build");
        Run("cmake", $"-S \"{source}\" -B \"{build}\" -DCMAKE_BUILD_TYPE=Release");
        Run("cmake", $"--build \"{build}\"");
        return build;
    }

    private static void Run(string file, string arguments)
    {
        using var process = Process.Start(new ProcessStartInfo(file, arguments) { RedirectStandardOutput = true, RedirectStandardError = true })
            ?? throw new InvalidOperationException($"cannot start {file}");
        var output = process.StandardOutput.ReadToEndAsync();
        var error = process.StandardError.ReadToEnd();
        process.WaitForExit();
        if (process.ExitCode != 0)
        {
            throw new InvalidOperationException($"{file} {arguments} failed: {output.Result}{error}");
        }
    }

    /// <summary>The repository's root folder.</summary>
    public static string RepoRoot()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            if (File.Exists(Path.Combine(dir.FullName, "RobotControl.sln")))
            {
                return dir.FullName;
            }
        }

        throw new InvalidOperationException("repository root not found");
    }
}
