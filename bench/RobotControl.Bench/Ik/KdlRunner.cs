using System.Diagnostics;
using System.Globalization;
using System.Text;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Bench.Ik;

/// <summary>
/// Runs Orocos KDL's ChainIkSolverPos_LMA and ChainIkSolverPos_NR_JL on the same targets through the kdl_ik program
/// (built from bench/kdl/kdl_ik.cpp by bench/kdl/build.sh). KDL times each solve itself (std::chrono::steady_clock); answers are checked here
/// with the same <see cref="SolveCheck"/> as every other solver.
/// </summary>
internal static class KdlRunner
{
    private const double MetresPerMm = 1e-3;

    public static List<SolverStats> Run(IkTargetSet set, SolveCheck check, int repeat, out string note)
    {
        var results = new List<SolverStats>();
        var script = FindBuildScript();
        if (script is null)
        {
            note = "bench/kdl/build.sh not found: KDL not run";
            return results;
        }

        var work = Path.Combine(Path.GetTempPath(), "robotcontrol-kdl-bench");
        Directory.CreateDirectory(work);
        var (buildCode, buildOutput) = Execute("/bin/sh", [script, work]);
        if (buildCode != 0)
        {
            note = $"KDL not available (build.sh exit {buildCode}): {buildOutput.Trim()}";
            return results;
        }

        var input = Path.Combine(work, "targets.txt");
        var output = Path.Combine(work, "results.txt");
        File.WriteAllText(input, Describe(set));
        var (code, runOutput) = Execute(Path.Combine(work, "kdl_ik"), [input, output, repeat.ToString(CultureInfo.InvariantCulture)]);
        if (code != 0)
        {
            note = $"kdl_ik failed (exit {code}): {runOutput.Trim()}";
            return results;
        }

        var n = set.Chain.JointCount;
        var count = set.Targets.Length;
        var bySolver = new Dictionary<string, (double[] Times, bool[] Solved, bool[] WithinTolerance)>(StringComparer.Ordinal);
        var q = new double[n];
        var cpu = new Dictionary<string, double>(StringComparer.Ordinal);
        foreach (var line in File.ReadLines(output))
        {
            var parts = line.Split(' ', StringSplitOptions.RemoveEmptyEntries);
            if (parts[0] == "cpu")
            {
                cpu[parts[1]] = double.Parse(parts[2], CultureInfo.InvariantCulture);
                continue;
            }

            var name = parts[0];
            var index = int.Parse(parts[1], CultureInfo.InvariantCulture);
            var us = double.Parse(parts[3], CultureInfo.InvariantCulture);
            for (var i = 0; i < n; i++)
            {
                q[i] = double.Parse(parts[4 + i], CultureInfo.InvariantCulture);
            }

            if (!bySolver.TryGetValue(name, out var entry))
            {
                entry = (new double[count], new bool[count], new bool[count]);
                Array.Fill(entry.Times, double.PositiveInfinity);
                bySolver[name] = entry;
            }

            // One line per pass and target: keep the fastest time (KDL is deterministic: every pass answers alike).
            entry.Times[index] = Math.Min(entry.Times[index], us);
            entry.WithinTolerance[index] = check.WithinTolerance(set.Targets[index], q);
            entry.Solved[index] = check.Solved(set.Targets[index], q);
        }

        foreach (var (name, entry) in bySolver)
        {
            var poseOnly = string.Create(CultureInfo.InvariantCulture, $"; pose within tolerance ignoring limits: {100.0 * entry.WithinTolerance.Count(b => b) / count:F2} %");
            results.Add(SolverStats.From(name, entry.Times, entry.Solved.Count(b => b),
                (name == "kdl_lma" ? "L=(1,1,1,0.1,0.1,0.1) eps=1e-7 maxiter=500, knows no joint limits (answers wrapped by whole turns, then checked)" : "pinv velocity solver, eps=1e-5, maxiter=100") + poseOnly)
                with { MeanCpuUs = cpu.GetValueOrDefault(name, double.NaN) });
        }

        note = "liborocos-kdl (Debian), g++ -O2, timed inside the C++ program";
        return results;
    }

    private static string Describe(IkTargetSet set)
    {
        var chain = set.Chain;
        var text = new StringBuilder();
        var inv = CultureInfo.InvariantCulture;
        text.Append(inv, $"rows {chain.RowCount}\n");
        var lastJoint = -1;
        foreach (var row in chain.Rows)
        {
            if (row.JointIndex >= 0)
            {
                if (row.JointIndex != lastJoint + 1)
                {
                    throw new InvalidOperationException("KDL runner expects joints in DH row order");
                }

                lastJoint = row.JointIndex;
            }

            text.Append(inv, $"{row.AlphaRad:R} {row.AMm * MetresPerMm:R} {row.DMm * MetresPerMm:R} {row.ThetaOffsetRad:R} {(row.JointIndex >= 0 ? 1 : 0)}\n");
        }

        text.Append(inv, $"joints {chain.JointCount}\n");
        for (var i = 0; i < chain.JointCount; i++)
        {
            text.Append(inv, $"{chain.MinRad[i]:R} {chain.MaxRad[i]:R}\n");
        }

        var seed = new double[chain.JointCount];
        chain.MidRange(seed);
        text.Append("seed");
        foreach (var v in seed)
        {
            text.Append(inv, $" {v:R}");
        }

        text.Append(inv, $"\ntargets {set.Targets.Length}\n");
        foreach (var t in set.Targets)
        {
            var p = t.Position * MetresPerMm;
            var r = t.Rotation;
            text.Append(inv, $"{p.X:R} {p.Y:R} {p.Z:R}");
            for (var row = 0; row < 3; row++)
            {
                for (var column = 0; column < 3; column++)
                {
                    text.Append(inv, $" {r.At(row, column):R}");
                }
            }

            text.Append('\n');
        }

        return text.ToString();
    }

    private static string? FindBuildScript()
    {
        for (var dir = new DirectoryInfo(Directory.GetCurrentDirectory()); dir is not null; dir = dir.Parent)
        {
            var candidate = Path.Combine(dir.FullName, "bench", "kdl", "build.sh");
            if (File.Exists(candidate))
            {
                return candidate;
            }
        }

        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            var candidate = Path.Combine(dir.FullName, "bench", "kdl", "build.sh");
            if (File.Exists(candidate))
            {
                return candidate;
            }
        }

        return null;
    }

    private static (int Code, string Output) Execute(string file, string[] arguments)
    {
        var info = new ProcessStartInfo(file) { RedirectStandardError = true, RedirectStandardOutput = true };
        foreach (var a in arguments)
        {
            info.ArgumentList.Add(a);
        }

        try
        {
            using var process = Process.Start(info)!;
            var stderr = process.StandardError.ReadToEndAsync();
            var stdout = process.StandardOutput.ReadToEnd();
            process.WaitForExit();
            return (process.ExitCode, stdout + stderr.Result);
        }
        catch (System.ComponentModel.Win32Exception ex)
        {
            return (-1, ex.Message);
        }
    }
}
