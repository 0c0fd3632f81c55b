using RobotControl.Host.Session;
using RobotControl.Bus.Protocol;
using RobotControl.Definitions.Model;
using RobotControl.Host.Harness;
using RobotControl.Host.Safety;
using RobotControl.Plugins.Touch;
using RobotControl.Plugins.Touch.Simulation;

namespace RobotControl.Host.Tests.Safety;

/// <summary>A headless virtual run of the shipped teleop graph with faults injected, its goal frames and the virtual modules read back at the end.</summary>
internal sealed class SafetyRun
{
    private SafetyRun(RunReport report, GoalFrameSpy spy, double originS, RunLevel level, IReadOnlyList<MotorEnd> motors, double lastForceS)
    {
        LastForceS = lastForceS;
        Report = report;
        Spy = spy;
        OriginS = originS;
        FinalLevel = level;
        Motors = motors;
    }

    public RunReport Report { get; }

    public GoalFrameSpy Spy { get; }

    /// <summary>Bus time of the run's start, s (report times count from it).</summary>
    public double OriginS { get; }

    public RunLevel FinalLevel { get; }

    public IReadOnlyList<MotorEnd> Motors { get; }

    /// <summary>Run time of the last tick on which a simulated haptic handle rendered a non-zero force, s (-inf: none).</summary>
    public double LastForceS { get; }

    public SafetyReport Safety => Report.Safety!;

    /// <summary>A run; <paramref name="afterRun"/> acts on the supervisor after the last tick, before the run level is read.</summary>
    public static SafetyRun Of(string inject, double seconds, string? graph = null, Action<SafetySupervisor>? afterRun = null) =>
        Of(inject, seconds, TimeSpan.FromMilliseconds(200), graph, afterRun);

    /// <summary>A run whose harness presses the pedal again <paramref name="reEngageAfter"/> after a soft trip (null: never).</summary>
    public static SafetyRun Of(string inject, double seconds, TimeSpan? reEngageAfter, string? graph = null, Action<SafetySupervisor>? afterRun = null)
    {
        var goal = ControlTable.Firmware["goal_position"];
        GoalFrameSpy? spy = null;
        double origin = 0;
        var lastForceS = double.NegativeInfinity;
        var level = RunLevel.Init;
        var motors = new List<MotorEnd>();
        var lastForceAt = long.MinValue;
        var report = HeadlessRun.RunVirtual(
            new RunOptions { GraphPath = graph ?? Graphs.Path("teleop-lb.json"), Duration = TimeSpan.FromSeconds(seconds), Inject = FaultInjection.Parse(inject), ReEngageAfter = reEngageAfter, TickCost = VirtualTickCost.Free },
            TestPlugins.Catalog(),
            new VirtualRunHooks
            {
                WrapLink = (link, clock) => spy = new GoalFrameSpy(link, clock, goal.At(0), goal.Stride),
                AroundTick = (loop, at) =>
                {
                    loop.Step();
                    foreach (var touch in loop.Program.Order.OfType<TouchPlugin>())
                    {
                        if (touch.Backend is SimulatedTouchBackend { LastRenderedForce: var f } && (f.XN != 0 || f.YN != 0 || f.ZN != 0))
                        {
                            lastForceAt = at;
                        }
                    }
                },
                AfterRun = session =>
                {
                    origin = session.Supervisor.Origin / (double)session.Clock.TimestampFrequency;
                    afterRun?.Invoke(session.Supervisor);
                    lastForceS = lastForceAt == long.MinValue ? double.NegativeInfinity : (lastForceAt - session.Supervisor.Origin) / (double)session.Clock.TimestampFrequency;
                    level = session.Supervisor.Level;
                    foreach (var m in session.Robot.Motors)
                    {
                        var axis = session.Simulation!.Axes.Single(a => a.Config.FullName == m.Config.FullName);
                        motors.Add(new MotorEnd(m.Config.FullName, m.Config.ModuleId, m.Config.Channel, m.Config.CountsPerRad, m.SpeedLimitRadS, axis.DriverEnabled, axis.OutputAngleRad, session.Robot.SentGoalRad(m)));
                    }
                },
            });
        return new SafetyRun(report, spy!, origin, level, motors, lastForceS);
    }

    /// <summary>A run of the shipped teleop graph on a copy of its robot file with <paramref name="safety"/> as its <c>safety</c> section.</summary>
    public static SafetyRun WithSafetySection(string safety, string inject, double seconds)
    {
        var dir = Directory.CreateTempSubdirectory("safety-");
        try
        {
            return Of(inject, seconds, GraphWithSafetySection(dir.FullName, safety));
        }
        finally
        {
            dir.Delete(recursive: true);
        }
    }

    /// <summary>
    /// Writes into <paramref name="dir"/> the shipped teleop graph on a copy of its robot file with
    /// <paramref name="safety"/> as its <c>safety</c> section; returns the graph's path.
    /// </summary>
    private static string GraphWithSafetySection(string dir, string safety)
    {
        var source = Graphs.Path("teleop-lb.json");
        var robotPath = Path.GetFullPath(Path.Combine(Path.GetDirectoryName(source)!, "../hardware/robots/lb-1.0.json"));
        var components = Path.GetFullPath(Path.Combine(Path.GetDirectoryName(robotPath)!, "../components")).Replace('\\', '/');
        var robot = File.ReadAllText(robotPath).Replace("\"../components/", $"\"{components}/", StringComparison.Ordinal).TrimEnd();
        robot = robot[..robot.LastIndexOf('}')] + $", \"safety\": {safety} }}";
        File.WriteAllText(Path.Combine(dir, "lb.json"), robot);
        var graph = Path.Combine(dir, "teleop.json");
        File.WriteAllText(graph, File.ReadAllText(source)
            .Replace("\"../hardware/robots/lb-1.0.json\"", "\"lb.json\"", StringComparison.Ordinal)
            .Replace("\"trajectories/", $"\"{Path.GetDirectoryName(source)!.Replace('\\', '/')}/trajectories/", StringComparison.Ordinal));
        return graph;
    }

    /// <summary>The first trip of <paramref name="check"/> (fails the test if none).</summary>
    public SafetyReport.TripEntry Trip(SafetyCheck check) =>
        Safety.Trips.FirstOrDefault(t => t.Check == check) ?? throw new Xunit.Sdk.XunitException($"no {check.Name()} trip; trips: {string.Join("; ", Safety.Trips.Select(t => $"{t.Check.Name()} {t.Joint} at {t.TimeSeconds}"))}");

    /// <summary>
    /// The largest goal step any frame the virtual robot received made, as a fraction of the step cap, while the motors
    /// are driven: up to the first torque-off trip, after which the goals only mirror the measured positions of motors
    /// that are off. The first frame (before any cap applies) is the reference.
    /// </summary>
    public double WorstStepOverCap()
    {
        var off = Safety.Trips.FirstOrDefault(t => t.Action == SafeState.TorqueOff)?.TimeSeconds ?? double.PositiveInfinity;
        return Spy.WorstStepOverCap(Motors.Select(m => (m.ModuleId, m.Channel, m.CountsPerRad, m.SpeedLimitRadS)), 1, OriginS + off);
    }

    /// <summary>The goal frames from <paramref name="fromS"/> to <paramref name="untilS"/> (run time), oldest first.</summary>
    public List<(double TimeS, Dictionary<byte, int[]> Goals)> FramesBetween(double fromS, double untilS) =>
        [.. Spy.Frames.Where(f => f.TimeS - OriginS >= fromS && f.TimeS - OriginS < untilS)];

    /// <summary>True when every goal frame from <paramref name="fromS"/> (run time) on carries the same goals.</summary>
    public bool GoalsFrozenFrom(double fromS) => GoalsFrozenBetween(fromS, double.PositiveInfinity);

    /// <summary>True when every goal frame from <paramref name="fromS"/> to <paramref name="untilS"/> (run time) carries the same goals.</summary>
    public bool GoalsFrozenBetween(double fromS, double untilS)
    {
        var frames = Spy.Frames.Where(f => f.TimeS - OriginS >= fromS && f.TimeS - OriginS < untilS).ToList();
        Assert.NotEmpty(frames);
        return frames.All(f => Motors.All(m => !f.Goals.TryGetValue(m.ModuleId, out var g) || g[m.Channel] == frames[0].Goals[m.ModuleId][m.Channel]));
    }
}

/// <summary>A motor at the end of a run: what its virtual module does.</summary>
internal sealed record MotorEnd(string Name, byte ModuleId, int Channel, double CountsPerRad, double SpeedLimitRadS, bool DriverEnabled, double OutputRad, double GoalRad);
