using System.Diagnostics;
using System.Globalization;
using System.Text.Json;
using RobotControl.Definitions.Loading;
using RobotControl.Host.Session;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Bench.Ik;

/// <summary>
/// <c>ik --replay OUT.json</c>: solves again every failure and every slowest target a previous <c>ik</c> run wrote, from
/// the seed it started from, and prints each one's outcome; exit 1 if any is still not solved.
/// </summary>
internal static class IkReplay
{
    public static int Run(string file, int repeat, JsonSerializerOptions json)
    {
        try
        {
            return Replay(file, repeat, json);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or JsonException
            or KeyNotFoundException or InvalidOperationException or FormatException or ArgumentException or RobotDataException)
        {
            Console.Error.WriteLine($"{file}: {e.Message}");
            return 2;
        }
    }

    private static int Replay(string file, int repeat, JsonSerializerOptions json)
    {
        using var document = JsonDocument.Parse(File.ReadAllText(file));
        var root = document.RootElement;
        if (!root.TryGetProperty("robot_file", out var robotFile) || !root.TryGetProperty("sets", out var sets))
        {
            Console.Error.WriteLine($"{file}: no 'robot_file' or 'sets': not written by `ik --json` with the target sets");
            return 2;
        }

        var robot = RobotLoader.Load(robotFile.GetString()!);
        var chain = new KinematicChain(robot);
        var options = new IkOptions();
        var check = new SolveCheck(chain, options.PositionToleranceMm, options.OrientationToleranceRad);
        var solver = new IkSolver(chain, options);
        var q = new double[chain.JointCount];
        var cases = new List<IkCase>();
        foreach (var set in sets.EnumerateArray())
        {
            foreach (var list in new[] { "failures", "worst" })
            {
                cases.AddRange(set.GetProperty(list).Deserialize<List<IkCase>>(json) ?? []);
            }
        }

        // Tiered JIT: solve the cases for a second before timing, as the benchmark does.
        var warm = Stopwatch.GetTimestamp();
        for (var i = 0; cases.Count > 0 && Stopwatch.GetElapsedTime(warm).TotalSeconds < 1.0; i++)
        {
            solver.Solve(cases[i % cases.Count].Target(), cases[i % cases.Count].SeedRad, q);
        }

        Thread.Sleep(300);
        var unsolved = 0;
        foreach (var item in cases)
        {
            var target = item.Target();
            var wall = double.PositiveInfinity;
            var cpu = double.PositiveInfinity;
            var result = default(IkResult);
            for (var pass = 0; pass < Math.Max(repeat, 1); pass++)
            {
                var cpuStart = ThreadCpuClock.NowNs();
                var start = Stopwatch.GetTimestamp();
                result = solver.Solve(target, item.SeedRad, q);
                wall = Math.Min(wall, Stopwatch.GetElapsedTime(start).TotalMicroseconds);
                cpu = Math.Min(cpu, (ThreadCpuClock.NowNs() - cpuStart) * 1e-3);
            }

            var solved = check.Solved(target, q);
            unsolved += solved ? 0 : 1;
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"{item.Set,-14} #{item.Index,-8} {(solved ? "solved" : "NOT SOLVED"),-10} {result.Status,-12} iterations {result.Iterations,4}  wall {wall,8:F2} us  cpu {cpu,8:F2} us  (was: {(item.Solved ? "solved" : "not solved")}, {item.Iterations} iterations, {item.WallUs:F2} us)"));
        }

        Console.WriteLine($"{cases.Count} targets replayed, {unsolved} not solved");
        return unsolved == 0 ? 0 : 1;
    }
}
