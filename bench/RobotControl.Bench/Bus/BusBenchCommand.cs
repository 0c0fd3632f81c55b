using System.Diagnostics;
using System.Globalization;
using System.Text.Json;
using RobotControl.Bench.Ik;
using RobotControl.Bus.Client;
using RobotControl.Definitions.Loading;
using RobotControl.Robot.Bus;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.Host.Session;

namespace RobotControl.Bench.Bus;

/// <summary>
/// <c>bus [--robot file] [--seconds s] [--repeats n] [--out file.json]</c>: full-state bus cycles (sync write of every
/// goal, sync read of every position/current) of a robot on the virtual bus at 1 and 3 Mbaud: cycles per simulated
/// second against the wire-time bound of the bytes each cycle puts on the wire, and host CPU per cycle (wall time
/// outside the simulated link; the firmware simulation's share is reported apart). On a shared machine wall time counts
/// the time the thread sat descheduled, so the thread's own CPU time per cycle (host and simulation, which run on the
/// one thread) is reported too, and the host's share of it estimated from the wall-time split.
/// </summary>
internal sealed class BusBenchCommand : IBenchCommand
{
    private static readonly JsonSerializerOptions JsonOptions = new() { WriteIndented = true };

    public string Name => "bus";

    public string Description => "Full-state bus cycles/s on the virtual bus at 1 and 3 Mbaud vs the wire-time bound; host CPU per cycle.";

    public int Run(string[] args)
    {
        var robotPath = BenchArgs.Value(args, "--robot") ?? "hardware/robots/lb-1.0.json";
        var seconds = double.Parse(BenchArgs.Value(args, "--seconds") ?? "2", CultureInfo.InvariantCulture);
        var repeats = int.Parse(BenchArgs.Value(args, "--repeats") ?? "5", CultureInfo.InvariantCulture);
        var outFile = BenchArgs.Value(args, "--out");
        var robot = RobotLoader.Load(robotPath);
        var results = new List<object>();
        Console.WriteLine($"{robot.Name}: {robot.Modules.Modules.Count} modules, {robot.Modules.Modules.Sum(m => m.Motors.Count)} motors; {seconds} s simulated per run, {repeats} runs, medians");
        Console.WriteLine("baud       cycles/s  bound/s  of bound  bytes/cycle  host us/cycle  sim us/cycle  alloc B/cycle  thread CPU us/cycle  host CPU us/cycle (est.)");
        foreach (var baud in new[] { 1_000_000, 3_000_000 })
        {
            var runs = Enumerable.Range(0, repeats).Select(_ => Measure(robot, baud, seconds)).ToList();
            var m = new
            {
                baud,
                cyclesPerSecond = Median(runs.Select(r => r.CyclesPerSecond)),
                boundPerSecond = Median(runs.Select(r => r.BoundPerSecond)),
                bytesPerCycle = Median(runs.Select(r => r.BytesPerCycle)),
                hostMicrosPerCycle = Median(runs.Select(r => r.HostMicros)),
                simMicrosPerCycle = Median(runs.Select(r => r.SimMicros)),
                allocatedBytesPerCycle = Median(runs.Select(r => r.AllocPerCycle)),
                threadCpuMicrosPerCycle = Median(runs.Select(r => r.ThreadCpuMicros)),
                hostCpuMicrosPerCycle = Median(runs.Select(r => r.HostCpuMicros)),
            };
            var ratio = m.cyclesPerSecond / m.boundPerSecond;
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"{baud,9}  {m.cyclesPerSecond,8:F1}  {m.boundPerSecond,7:F1}  {ratio * 100,7:F1} %  {m.bytesPerCycle,11:F1}  {m.hostMicrosPerCycle,13:F1}  {m.simMicrosPerCycle,12:F1}  {m.allocatedBytesPerCycle,13:F1}  {m.threadCpuMicrosPerCycle,19:F1}  {m.hostCpuMicrosPerCycle,24:F2}"));
            results.Add(new { m.baud, m.cyclesPerSecond, m.boundPerSecond, ratioOfBound = ratio, m.bytesPerCycle, m.hostMicrosPerCycle, m.simMicrosPerCycle, m.allocatedBytesPerCycle, m.threadCpuMicrosPerCycle, m.hostCpuMicrosPerCycle, runs = runs.Count });
        }

        if (outFile is not null)
        {
            File.WriteAllText(outFile, JsonSerializer.Serialize(new { robot = robot.Name, seconds, repeats, results }, JsonOptions));
        }

        return 0;
    }

    private static RunResult Measure(RobotControl.Definitions.Model.RobotDefinition robot, int baud, double seconds)
    {
        var clock = new ManualTimeProvider();
        using var sim = new VirtualRobot(robot, clock, new VirtualRobotOptions { BaudRate = baud });
        var link = new TimedLink(sim.OpenLink());
        // Status polls are left out: this measures the full-state cycle itself.
        using var bus = new BusRobot(robot, new BusClient(link, clock), new BusRobotOptions { StatusPollCycles = int.MaxValue, ReprobeCycles = int.MaxValue });
        bus.Discover();
        bus.EnableTorque(true);
        bus.RunFor(TimeSpan.FromMilliseconds(50)); // warm up (JIT, first moves)

        var q = robot.Joints.Select(j => j.MidRad).ToArray();
        var cycles0 = bus.Cycles;
        var bytes0 = sim.WireBytes;
        var t0 = clock.GetTimestamp();
        var inside0 = link.InsideTicks;
        var alloc0 = GC.GetAllocatedBytesForCurrentThread();
        var cpu0 = ThreadCpuClock.NowUs();
        var wall = Stopwatch.StartNew();
        var end = t0 + (long)(seconds * clock.TimestampFrequency);
        var k = 0;
        while (clock.GetTimestamp() < end)
        {
            // A moving setpoint, as the control loop would publish it.
            q[3] = robot.Joints[3].MidRad + (0.3 * Math.Sin(k++ * 0.01));
            bus.WriteJointSetpoints(0, q);
            bus.RunCycle();
        }

        wall.Stop();
        var cpuMicros = ThreadCpuClock.NowUs() - cpu0;
        var cycles = bus.Cycles - cycles0;
        var simulated = (clock.GetTimestamp() - t0) / (double)clock.TimestampFrequency;
        var bytesPerCycle = (sim.WireBytes - bytes0) / (double)cycles;
        var insideSeconds = (link.InsideTicks - inside0) / (double)Stopwatch.Frequency;
        var hostShare = (wall.Elapsed.TotalSeconds - insideSeconds) / wall.Elapsed.TotalSeconds;
        return new RunResult(
            cycles / simulated,
            baud / 10.0 / bytesPerCycle,
            bytesPerCycle,
            (wall.Elapsed.TotalSeconds - insideSeconds) * 1e6 / cycles,
            insideSeconds * 1e6 / cycles,
            (GC.GetAllocatedBytesForCurrentThread() - alloc0) / (double)cycles,
            cpuMicros / cycles,
            cpuMicros * hostShare / cycles);
    }

    private static double Median(IEnumerable<double> values)
    {
        var v = values.Order().ToArray();
        return v.Length % 2 == 1 ? v[v.Length / 2] : 0.5 * (v[(v.Length / 2) - 1] + v[v.Length / 2]);
    }


    private sealed record RunResult(double CyclesPerSecond, double BoundPerSecond, double BytesPerCycle, double HostMicros, double SimMicros, double AllocPerCycle, double ThreadCpuMicros, double HostCpuMicros);
}
