using BenchmarkDotNet.Configs;
using BenchmarkDotNet.Jobs;
using BenchmarkDotNet.Running;
using BenchmarkDotNet.Toolchains.InProcess.Emit;

namespace RobotControl.Bench.Ik;

/// <summary><c>ik-alloc [--robot FILE]</c>: BenchmarkDotNet with [MemoryDiagnoser] on one solve (in-process, short job).</summary>
internal sealed class IkAllocCommand : IBenchCommand
{
    public string Name => "ik-alloc";

    public string Description => "inverse kinematics: BenchmarkDotNet memory diagnoser (bytes allocated per solve)";

    public int Run(string[] args)
    {
        if (args.Length >= 2 && args[0] == "--robot")
        {
            IkAllocBenchmarks.RobotFile = Path.GetFullPath(args[1]);
        }
        else
        {
            IkAllocBenchmarks.RobotFile = Path.GetFullPath(IkAllocBenchmarks.RobotFile);
        }

        var config = ManualConfig.CreateMinimumViable()
            .AddJob(Job.ShortRun.WithToolchain(InProcessEmitToolchain.Instance))
            .WithOptions(ConfigOptions.DisableOptimizationsValidator);
        var summary = BenchmarkRunner.Run<IkAllocBenchmarks>(config);
        return summary.HasCriticalValidationErrors ? 1 : 0;
    }
}
