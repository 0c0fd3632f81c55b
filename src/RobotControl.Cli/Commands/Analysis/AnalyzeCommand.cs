using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using RobotControl.Analysis;
using RobotControl.Analysis.Output;
using RobotControl.Analysis.Sweep;
using RobotControl.Analysis.Workspace;
using RobotControl.Cli.Options;
using RobotControl.Definitions.Loading;
using RobotControl.Definitions.Model;
using Spectre.Console;

namespace RobotControl.Cli.Commands.Analysis;

/// <summary>
/// <c>robotctl analyze &lt;robot file&gt; --out &lt;dir&gt;</c>: capability analysis (drivetrain, sweep maps, requirements,
/// workspace volumes, current limits). Nothing is written unless the whole analysis succeeds.
/// </summary>
internal sealed class AnalyzeCommand : ICliCommand
{
    public Command Build()
    {
        var robotArgument = new Argument<FileInfo>("robot")
        {
            Description = "Robot file, e.g. hardware/robots/lb-1.0.json",
        };
        var outOption = CliOption.OutputDirectory("--out", "-o", "Output directory (created if missing): summary.json, sweep.csv and the PNG maps");
        var sweepOption = new Option<string?>("--sweep")
        {
            Description = "Grid to sweep instead of the robot file's reference cross-section, in degrees: " +
                          "x_joint:min:max,y_joint:min:max[,step=1][,fixed=joint:value]...[,used=j1+j2+j3] " +
                          "(joints by name or symbol; unnamed joints keep the file's values)",
        };
        var couplingOption = new Option<bool>("--coupling-aware")
        {
            Description = "Also evaluate velocity and force with the limits applied to the motors behind the shoulder couplings (reported separately)",
        };
        var voxelOption = CliOption.Number("--voxel-mm", "Workspace cell size h in mm (volumes are extrapolated from h and 2h)", 0.01, 1000.0, WorkspaceCalculator.DefaultVoxelMm);
        var noWorkspaceOption = new Option<bool>("--no-workspace")
        {
            Description = "Skip the workspace volumes",
        };

        var command = new Command("analyze", "Capability analysis of a robot design: drivetrain, velocity, force, manipulability, workspace, current limits")
        {
            robotArgument, outOption, sweepOption, couplingOption, voxelOption, noWorkspaceOption,
        };
        command.SetAction(parse => Run(
            parse.GetRequiredValue(robotArgument),
            parse.GetRequiredValue(outOption),
            parse.GetValue(sweepOption),
            parse.GetValue(couplingOption),
            parse.GetValue(voxelOption),
            !parse.GetValue(noWorkspaceOption),
            parse.InvocationConfiguration.Output,
            parse.InvocationConfiguration.Error));
        return command;
    }

    private static int Run(FileInfo robotFile, DirectoryInfo outDir, string? sweep, bool couplingAware, double voxelMm, bool workspace, TextWriter output, TextWriter error)
    {
        RobotDefinition robot;
        AnalysisOptions options;
        try
        {
            robot = RobotLoader.Load(robotFile.FullName);
            options = new AnalysisOptions
            {
                Sweep = sweep is null ? null : SweepSpecificationParser.Parse(sweep, robot),
                CouplingAware = couplingAware,
                Workspace = workspace,
                WorkspaceVoxelMm = voxelMm,
            };
            if (AnalysisBudget.Check(robot, options.Sweep ?? SweepSpecification.FromCrossSection(robot.CrossSection), workspace, voxelMm) is { } tooLarge)
            {
                throw new FormatException(tooLarge);
            }
        }
        catch (Exception ex) when (ex is RobotDataException or FormatException)
        {
            error.WriteLine($"error: {ex.Message}");
            error.WriteLine("nothing was written.");
            return 1;
        }

        var clock = Stopwatch.StartNew();
        try
        {
            IReadOnlyList<string> files;
            AnalysisReport report;
            if (Console.IsOutputRedirected || !ReferenceEquals(output, Console.Out))
            {
                var plain = new PlainProgress(output);
                report = CapabilityAnalyzer.Run(robot, options, plain);
                files = AnalysisOutputWriter.Write(report, outDir.FullName, plain);
            }
            else
            {
                (report, files) = RunWithProgressBar(robot, options, outDir.FullName);
            }

            PrintSummary(output, report, files, outDir.FullName, clock.Elapsed);
            return 0;
        }
        catch (Exception ex) when (ex is ArgumentException or InvalidOperationException)
        {
            // InvalidOperationException: the maps' font is missing (AnalysisOutputWriter checks before writing).
            error.WriteLine($"error: {ex.Message}");
            error.WriteLine("nothing was written.");
            return 1;
        }
    }

    private static (AnalysisReport Report, IReadOnlyList<string> Files) RunWithProgressBar(RobotDefinition robot, AnalysisOptions options, string outDir)
    {
        AnalysisReport? report = null;
        IReadOnlyList<string>? files = null;
        AnsiConsole.Progress()
            .Columns(new TaskDescriptionColumn(), new ProgressBarColumn(), new PercentageColumn(), new ElapsedTimeColumn())
            .Start(ctx =>
            {
                var task = ctx.AddTask($"analyze {robot.Name}", maxValue: 1.0);
                var sync = new SynchronousProgress(p =>
                {
                    task.Description = $"{robot.Name}: {p.Stage}";
                    task.Value = Math.Max(task.Value, p.Fraction);
                });
                report = CapabilityAnalyzer.Run(robot, options, sync);
                files = AnalysisOutputWriter.Write(report, outDir, sync);
                task.Value = 1.0;
            });
        return (report!, files!);
    }

    private static void PrintSummary(TextWriter o, AnalysisReport report, IReadOnlyList<string> files, string outDir, TimeSpan elapsed)
    {
        var inv = CultureInfo.InvariantCulture;
        var sweep = report.Sweep;
        o.WriteLine(string.Create(inv, $"{report.Robot.Name}: {sweep.Count} sweep points, {files.Count} files in {outDir} ({elapsed.TotalSeconds:F2} s)"));
        foreach (var d in report.Drivetrain)
        {
            o.WriteLine(string.Create(inv, $"  drive {d.Joint ?? d.Actuator,-16} {d.TorqueMNm,9:F1} mNm {d.SpeedRpm,8:F2} rpm"));
        }

        string[] axes = ["x", "y", "z"];
        for (var a = 0; a < 3; a++)
        {
            var v = Statistics.Of(sweep.Reference.Velocity[a]);
            var f = Statistics.Of(sweep.Reference.Force[a]);
            o.WriteLine(string.Create(
                inv,
                $"  {axes[a]}: velocity mean {v.Mean:F1} (min {v.Min:F1}, max {v.Max:F1}) mm/s, met {report.Requirements.VelocityFractionMet[a]:P1}; " +
                $"force mean {f.Mean:F2} (min {f.Min:F1}, max {f.Max:F1}) N, met {report.Requirements.ForceFractionMet[a]:P1}"));
        }

        if (report.Workspace is { } ws)
        {
            o.WriteLine(string.Create(inv, $"  workspace: arm {ws.ArmCm3:F0} cm³, union {ws.UnionCm3:F0} cm³, shared {ws.SharedCm3:F0} cm³ (h = {ws.Fine.VoxelMm} mm, extrapolated)"));
        }
    }

    /// <summary>Plain progress lines for redirected output.</summary>
    private sealed class PlainProgress(TextWriter output) : IProgress<AnalysisProgress>
    {
        private readonly Lock _gate = new();

        public void Report(AnalysisProgress value)
        {
            if (value.Elapsed is { } elapsed)
            {
                lock (_gate)
                {
                    output.WriteLine(string.Create(CultureInfo.InvariantCulture, $"analyze: {value.Stage} done in {elapsed.TotalSeconds:F2} s"));
                }
            }
        }
    }

    /// <summary>Reports on the calling thread (Spectre's progress context is thread-safe).</summary>
    private sealed class SynchronousProgress(Action<AnalysisProgress> report) : IProgress<AnalysisProgress>
    {
        public void Report(AnalysisProgress value) => report(value);
    }
}
