using System.Globalization;
using RobotControl.Bus.Client;
using RobotControl.Bus.Transports;
using RobotControl.Hardware.Model;
using RobotControl.Robot.Bus;
using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.GraphFiles;
using RobotControl.Runtime.Loop;
using RobotControl.Runtime.Robot;
using RobotControl.Simulation;
using RobotControl.Simulation.Bus;
using RobotControl.Simulation.Time;

namespace RobotControl.Runtime.Harness;

/// <summary>
/// The headless run: loads a graph file, connects its robot node to a robot (the virtual robot running the real
/// module firmware on a virtual clock, or the graph's transport in real time), runs the control loop for a duration
/// while measuring tick times, deadline misses and tracking error, and reports bus statistics and faults.
/// <para>
/// Virtual composition, per tick: <see cref="ControlLoop.Step"/> (Touch -> conditioning -> IK -> robot node writes
/// setpoints to the <see cref="BusRobot"/>), then one bus cycle (sync write of every goal, sync read of every
/// position and current: the virtual wire's time passes as bytes move and the firmware and motor models run),
/// then the simulation runs on to the next tick's due time. Deterministic: the same graph, duration, faults and
/// seed give the same report (tick times apart, which are measured CPU time).
/// </para>
/// </summary>
public static class HeadlessRun
{
    /// <summary>Runs <paramref name="options"/> with plug-in types from <paramref name="catalog"/>.</summary>
    /// <exception cref="Graph.GraphException">The graph file is invalid.</exception>
    /// <exception cref="InvalidOperationException">The graph names no robot, or the robot cannot be brought up.</exception>
    public static RunReport Run(RunOptions options, PluginCatalog catalog, Action<RunProgress>? progress = null)
    {
        ArgumentNullException.ThrowIfNull(options);
        ArgumentNullException.ThrowIfNull(catalog);
        return options.Virtual ? RunVirtual(options, catalog, progress, null) : RunRealTime(options, catalog, progress);
    }

    /// <summary>A virtual run with measurement hooks (benchmarks): a wrapper around the bus link, and one around each tick.</summary>
    internal static RunReport RunVirtual(RunOptions options, PluginCatalog catalog, VirtualRunHooks hooks) => RunVirtual(options, catalog, null, hooks);

    /// <summary>Joint angles per arm that the graph will command first (the initial values on the wires into the robot node).</summary>
    public static IReadOnlyList<double[]> InitialCommand(LoadedGraph loaded)
    {
        ArgumentNullException.ThrowIfNull(loaded);
        var robot = loaded.Robot ?? throw new InvalidOperationException("the graph names no robot");
        var outputs = loaded.Program.OutputSignals;
        var result = new List<double[]>();
        foreach (var arm in robot.Arms)
        {
            var q = robot.Joints.Select(j => j.MidRad).ToArray();
            for (var j = 0; j < q.Length; j++)
            {
                var wire = loaded.Document.Wires.FirstOrDefault(w => w.To == $"{RobotNode.InstanceName}.{arm.Name}.{robot.Joints[j].Name}");
                if (wire is not null)
                {
                    var index = IndexOf(outputs.Names, wire.From);
                    q[j] = Math.Clamp(outputs.Values[index], robot.Joints[j].MinRad, robot.Joints[j].MaxRad);
                }
            }

            result.Add(q);
        }

        return result;
    }

    private static RunReport RunVirtual(RunOptions options, PluginCatalog catalog, Action<RunProgress>? progress, VirtualRunHooks? hooks)
    {
        var clock = new ManualTimeProvider();
        var loaded = GraphFile.Load(options.GraphPath, catalog, clock, options.SettingOverrides);
        var robot = loaded.Robot ?? throw new InvalidOperationException($"{loaded.Path}: the graph names no robot file");
        var node = loaded.RobotNode!;
        var faults = new List<FaultEntry>();
        using var sim = new VirtualRobot(robot, clock, new VirtualRobotOptions { InitialJointsRad = InitialCommand(loaded), Seed = options.Seed });
        var link = sim.OpenLink();
        using var bus = new BusRobot(robot, new BusClient(hooks?.WrapLink?.Invoke(link, clock) ?? link, clock));
        var discovery = bus.Discover();
        faults.AddRange(discovery.Lines().Where(l => !l.StartsWith("found", StringComparison.Ordinal)).Select(l => new FaultEntry(0, "robot", l.Trim())));
        bus.EnableTorque(true);
        node.Attach(bus);
        var begin = clock.GetTimestamp();
        foreach (var reset in options.Inject.Resets)
        {
            sim.ScheduleReset(ResolveModule(robot, reset.Module), sim.Elapsed + reset.At);
        }

        if (options.Inject.BitErrorRate > 0)
        {
            sim.WireFaults = new WireFaults { BitErrorRate = options.Inject.BitErrorRate };
        }

        var meter = new TrackingMeter(node, bus);
        using var loop = new ControlLoop(loaded.Program, clock, loaded.Document.LoopRateHz, meter);
        var ticks = (long)Math.Round(options.Duration.TotalSeconds * loop.RateHz);
        var progressEvery = Math.Max(1, (long)Math.Round(options.ProgressInterval.TotalSeconds * loop.RateHz));
        Elapsed elapsed = () => clock.GetElapsedTime(begin);

        // The loop ticks from a periodic timer on the virtual clock, the bus cycles back to back on this thread: as
        // the cycles move the clock (bytes on the wire, firmware and motors simulated), the timer fires every due
        // tick at its exact time, in between. That is the deterministic equivalent of a loop thread and a bus thread
        // exchanging latest values, whatever a bus cycle costs relative to the loop period.
        Action<ControlLoop> step = hooks?.AroundTick ?? (l => l.Step());
        using (var timer = clock.CreateTimer(_ => TickIfDue(loop, ticks, step), null, loop.Period, loop.Period))
        {
            var reported = 0L;
            while (loop.TickCount < ticks)
            {
                bus.RunCycle();
                if (loop.TickCount - reported >= progressEvery || loop.TickCount >= ticks)
                {
                    reported = loop.TickCount;
                    DrainEvents(bus, elapsed(), faults);
                    progress?.Invoke(Progress(loop, meter, elapsed(), options.Duration, faults.Count + loaded.Program.FaultCount, bus.Faults.ToString()));
                }
            }
        }

        loop.Stop();
        DrainEvents(bus, elapsed(), faults);
        return Report(loop, meter, elapsed(), loaded, bus, faults);
    }

    private static RunReport RunRealTime(RunOptions options, PluginCatalog catalog, Action<RunProgress>? progress)
    {
        if (!options.Inject.IsNone)
        {
            throw new InvalidOperationException("--inject applies to the virtual robot only (add --virtual)");
        }

        var clock = TimeProvider.System;
        var loaded = GraphFile.Load(options.GraphPath, catalog, clock, options.SettingOverrides);
        var robot = loaded.Robot ?? throw new InvalidOperationException($"{loaded.Path}: the graph names no robot file");
        var transport = loaded.Document.Transport;
        if (transport.StartsWith("virtual", StringComparison.OrdinalIgnoreCase))
        {
            throw new InvalidOperationException($"the graph's transport is '{transport}': run it with --virtual, or name a serial, usb or tcp transport");
        }

        var faults = new List<FaultEntry>();
        using var bus = new BusRobot(robot, new BusClient(LinkFactory.Open(transport), clock));
        var discovery = bus.Discover();
        faults.AddRange(discovery.Lines().Where(l => !l.StartsWith("found", StringComparison.Ordinal)).Select(l => new FaultEntry(0, "robot", l.Trim())));
        bus.EnableTorque(true);
        loaded.RobotNode!.Attach(bus);
        var meter = new TrackingMeter(loaded.RobotNode, bus);
        using var loop = new ControlLoop(loaded.Program, clock, loaded.Document.LoopRateHz, meter);
        var begin = clock.GetTimestamp();
        bus.Start();
        loop.Start();
        try
        {
            while (clock.GetElapsedTime(begin) < options.Duration && loop.ThreadFailure is null)
            {
                Thread.Sleep(options.ProgressInterval < options.Duration ? options.ProgressInterval : options.Duration);
                DrainEvents(bus, clock.GetElapsedTime(begin), faults);
                progress?.Invoke(Progress(loop, meter, clock.GetElapsedTime(begin), options.Duration, faults.Count + loaded.Program.FaultCount, bus.Faults.ToString()));
            }
        }
        finally
        {
            loop.Stop();
            bus.Stop();
            bus.EnableTorque(false);
        }

        if (loop.ThreadFailure is { } failure)
        {
            faults.Add(new FaultEntry(clock.GetElapsedTime(begin).TotalSeconds, "harness", $"control loop failed: {failure.Message}"));
        }

        DrainEvents(bus, clock.GetElapsedTime(begin), faults);
        return Report(loop, meter, clock.GetElapsedTime(begin), loaded, bus, faults);
    }

    private delegate TimeSpan Elapsed();

    private static void TickIfDue(ControlLoop loop, long ticks, Action<ControlLoop> step)
    {
        if (loop.TickCount < ticks)
        {
            step(loop);
        }
    }

    private static RunProgress Progress(ControlLoop loop, TrackingMeter meter, TimeSpan elapsed, TimeSpan duration, int faults, string robotFaults) =>
        new(elapsed, duration, loop.TickCount, loop.Statistics.DeadlineMisses, meter.RmsMm, meter.LastErrorMm.Max(), faults, robotFaults);

    private static RunReport Report(ControlLoop loop, TrackingMeter meter, TimeSpan elapsed, LoadedGraph loaded, BusRobot bus, List<FaultEntry> faults)
    {
        var all = faults
            .Concat(loaded.Program.Faults.Select(f => new FaultEntry(f.Time.TotalSeconds, f.Instance, f.Message)))
            .OrderBy(f => f.TimeSeconds)
            .ToList();
        if (loaded.RobotNode is { RejectedSetpoints: > 0 } node)
        {
            all.Add(new FaultEntry(elapsed.TotalSeconds, RobotNode.InstanceName, $"{node.RejectedSetpoints} non-finite setpoint vectors refused"));
        }

        long frames = 0, crc = 0, timeouts = 0, retries = 0;
        foreach (var controller in bus.Controllers)
        {
            var s = bus.Client.Statistics(controller.Id);
            frames += s.FramesSent + s.FramesReceived;
            crc += s.CrcErrors;
            timeouts += s.Timeouts;
            retries += s.Retries;
        }

        var stats = loop.Statistics;
        return new RunReport(
            elapsed.TotalSeconds,
            loop.TickCount,
            stats.DeadlineMisses,
            stats.MedianUs,
            stats.P99Us,
            stats.MaxUs,
            meter.RmsMm,
            meter.MaxMm,
            new BusReport(frames, crc, timeouts, retries),
            all);
    }

    private static void DrainEvents(BusRobot bus, TimeSpan at, List<FaultEntry> faults)
    {
        while (bus.Events.TryDequeue(out var line))
        {
            faults.Add(new FaultEntry(at.TotalSeconds, "robot", line));
        }
    }

    private static byte ResolveModule(RobotDefinition robot, string module)
    {
        if (byte.TryParse(module, NumberStyles.None, CultureInfo.InvariantCulture, out var id) && robot.Modules.ById(id) is not null)
        {
            return id;
        }

        foreach (var m in robot.Modules.Modules)
        {
            var arm = m.Arm >= 0 && m.Arm < robot.Arms.Count ? robot.Arms[m.Arm].Name : "";
            if (string.Equals($"{arm}.{m.Location}", module, StringComparison.OrdinalIgnoreCase) || string.Equals(m.Name, module, StringComparison.OrdinalIgnoreCase))
            {
                return m.Id;
            }
        }

        throw new FormatException($"--inject: no module '{module}' (known: {string.Join(", ", robot.Modules.Modules.Select(m => $"{(m.Arm >= 0 && m.Arm < robot.Arms.Count ? robot.Arms[m.Arm].Name : "?")}.{m.Location} (id {m.Id})"))})");
    }

    private static int IndexOf(IReadOnlyList<string> names, string name)
    {
        for (var i = 0; i < names.Count; i++)
        {
            if (names[i] == name)
            {
                return i;
            }
        }

        return -1;
    }
}
