using System.Diagnostics;
using System.Globalization;
using RobotControl.CoppeliaSim.Tests;
using RobotControl.Plugins.CoppeliaSim;
using RobotControl.Runtime.GraphFiles;
using RobotControl.Host.Harness;
using RobotControl.Host.Session;
using RobotControl.Runtime.Loop;

namespace RobotControl.Plugins.CoppeliaSim.Tests;

public sealed class CoppeliaSimPluginTests
{
    [Fact]
    public void Teleop_graph_on_the_virtual_robot_sends_the_ik_outputs_of_one_tick_and_reports_them_back()
    {
        // The run is paced to wall time and ends once enough reports have been checked: the bridge thread connects
        // on its own time (sim.getObject per joint), which a loaded machine can stretch past a few seconds.
        using var enough = new CancellationTokenSource();
        var joints = BridgeTestSupport.Joints;
        using var server = new FakeCoppeliaSim(joints.Select(j => j.Path));
        var ikByTick = new List<double[]>();
        int[]? ik = null;
        int[]? reported = null;
        CoppeliaSimPlugin? plugin = null;
        long lastChecked = -1;
        var checkedTicks = 0;
        var wall = Stopwatch.StartNew();
        var hooks = new VirtualRunHooks
        {
            AroundTick = (loop, _) =>
            {
                loop.Step();
                Pace(loop, wall);
                var names = loop.Program.OutputSignals.Names.ToList();
                plugin ??= loop.Program.Order.OfType<CoppeliaSimPlugin>().Single();
                ik ??= [.. joints.Select(j => names.IndexOf($"ik_{j.Signal}"))]; // ik_right.elbow feeds sim.right.elbow
                reported ??= [.. joints.Select(j => names.IndexOf($"sim.{j.Signal}.position"))];
                var values = loop.Program.OutputSignals.Values.ToArray();
                ikByTick.Add([.. ik.Select(i => values[i])]);
                var tick = plugin.LastReportTick;
                if (tick >= 0 && tick != lastChecked)
                {
                    Assert.Equal(ikByTick[(int)tick], reported.Select(i => values[i]).ToArray());
                    lastChecked = tick;
                    if (++checkedTicks >= 10)
                    {
                        enough.Cancel();
                    }
                }
            },
        };
        var options = new RunOptions
        {
            GraphPath = Path.Combine(BridgeTestSupport.Root, "graphs/teleop-lb-coppeliasim.json"),
            Duration = TimeSpan.FromSeconds(30),
            Stop = enough.Token,
            SettingOverrides = [new SettingOverride("sim", "endpoint", server.Endpoint)],
            TickCost = VirtualTickCost.Free, // the run's ticks are compared, not timed
        };

        var report = HeadlessRun.RunVirtual(options, BridgeTestSupport.Catalog(), hooks);

        Assert.All(ik!, i => Assert.True(i >= 0));
        Assert.All(reported!, i => Assert.True(i >= 0));
        Assert.Empty(report.Faults);
        Assert.True(checkedTicks >= 3, $"only {checkedTicks} reports came back");

        var known = ikByTick.Select(Key).ToHashSet();
        // Every batch the simulator received (one call per joint, in port order) is the IK output of one tick. A call
        // that fails (e.g. a reply later than the call timeout on a loaded machine) makes the bridge reconnect, which
        // starts with sim.getObject and may leave that session's last batch short; batches are checked per session.
        var sessions = new List<List<(string Func, IReadOnlyList<object?> Args)>>();
        foreach (var r in server.Requests)
        {
            if (r.Func == "sim.getObject" && (sessions.Count == 0 || sessions[^1].Count > 0))
            {
                sessions.Add([]);
            }
            else if (r.Func == "sim.setJointPosition" && sessions.Count > 0)
            {
                sessions[^1].Add(r);
            }
        }

        Assert.True(sessions.Count <= 3, $"{sessions.Count} sessions: the bridge kept reconnecting");
        var batches = 0;
        foreach (var sets in sessions)
        {
            for (var b = 0; b + joints.Count <= sets.Count; b += joints.Count)
            {
                var batch = sets.Skip(b).Take(joints.Count).ToList();
                Assert.Equal(Enumerable.Range(0, joints.Count).Select(i => 10L + i), batch.Select(r => (long)r.Args[0]!));
                Assert.Contains(Key([.. batch.Select(r => (double)r.Args[1]!)]), known);
                batches++;
            }
        }

        Assert.True(batches >= 3, $"only {batches} complete batches");
    }

    [Fact]
    public void Killed_simulator_mid_run_shows_as_disconnected_while_the_loop_ticks_on_and_the_bridge_reconnects()
    {
        // The run is paced to wall time and ends once the scenario is through (with some ticks after it); its length
        // is only a ceiling, since a loaded machine can stretch connection, detection and back-off by seconds.
        using var done = new CancellationTokenSource();
        var joints = BridgeTestSupport.Joints;
        using var server = new FakeCoppeliaSim(joints.Select(j => j.Path));
        var phase = KillPhase.Connecting;
        var flowingSince = -1L;
        var reportsAtLoss = 0L;
        var ticksWhileHung = 0; // from the kill to the bridge's call timing out: its call hangs (nothing answers)
        var connectedSeen = new List<double>();
        CoppeliaSimPlugin? plugin = null;
        var wall = Stopwatch.StartNew();
        var hooks = new VirtualRunHooks
        {
            AroundTick = (loop, _) =>
            {
                loop.Step();
                Pace(loop, wall);
                plugin ??= loop.Program.Order.OfType<CoppeliaSimPlugin>().Single();
                var connected = plugin.GetOutput("connected");
                if (connectedSeen.Count == 0 || connectedSeen[^1] != connected)
                {
                    connectedSeen.Add(connected);
                }

                switch (phase)
                {
                    case KillPhase.Connecting when connected == 1 && plugin.Reports > 3:
                        server.Kill();
                        phase = KillPhase.Killed;
                        break;
                    case KillPhase.Killed when connected == 1:
                        ticksWhileHung++;
                        break;
                    case KillPhase.Killed when connected == 0:
                        reportsAtLoss = plugin.Reports;
                        server.Start();
                        phase = KillPhase.Restarted;
                        break;
                    case KillPhase.Restarted when connected == 1 && plugin.Reports > reportsAtLoss + 3:
                        phase = KillPhase.Flowing;
                        flowingSince = loop.TickCount;
                        break;
                    case KillPhase.Flowing when loop.TickCount - flowingSince >= 500:
                        done.Cancel();
                        break;
                }
            },
        };
        var options = new RunOptions
        {
            GraphPath = Path.Combine(BridgeTestSupport.Root, "graphs/teleop-lb-coppeliasim.json"),
            Duration = TimeSpan.FromSeconds(90),
            Stop = done.Token,
            SettingOverrides = [new SettingOverride("sim", "endpoint", server.Endpoint), new SettingOverride("sim", "call_timeout_ms", "300")],
            TickCost = VirtualTickCost.Free,
        };

        var report = HeadlessRun.RunVirtual(options, BridgeTestSupport.Catalog(), hooks);

        Assert.True(phase == KillPhase.Flowing, $"stopped at {phase} after {report.Ticks} ticks; connected went {string.Join(",", connectedSeen)}");
        // Down, up, down when killed, up again; a heavily loaded machine may add a late reply counted as a loss.
        Assert.Equal([0.0, 1.0, 0.0, 1.0], connectedSeen.Take(4));
        Assert.True(plugin!.Sessions >= 2);
        // The loop never waits for the bridge: while the bridge's call to the dead simulator hung for its 300 ms timeout,
        // the ticks (paced to the wall clock at 1 kHz) went on. A tick that waited for the call would let one tick, at
        // most two, through before the bridge gave up.
        Assert.True(ticksWhileHung > 20, $"only {ticksWhileHung} ticks ran while the bridge's call hung");
        Assert.Empty(report.Faults);
    }

    [Fact]
    public void Stepping_steps_the_simulator_once_per_ticks_per_step()
    {
        var joints = BridgeTestSupport.Joints;
        using var server = new FakeCoppeliaSim(joints.Select(j => j.Path)) { WaitsPerStep = 1 };
        var json = $$"""
            {
              "schema": "robotcontrol/graph/1",
              "robot": "{{Path.Combine(BridgeTestSupport.Root, "hardware/robots/lb-1.0.json")}}",
              "instances": [ { "name": "sim", "type": "coppeliasim", "settings": { "endpoint": "{{server.Endpoint}}", "stepping": true, "ticks_per_step": 10, "call_timeout_ms": 10000 } } ],
              "wires": []
            }
            """;
        var loaded = GraphFile.LoadFromText(json, Path.Combine(BridgeTestSupport.Root, "graphs/step-test.json"), BridgeTestSupport.Catalog(), TimeProvider.System);
        loaded.RobotNode!.Attach(new HeldRobotPort(BridgeTestSupport.Lb));
        var plugin = loaded.Program.Order.OfType<CoppeliaSimPlugin>().Single();
        using var loop = new ControlLoop(loaded.Program, TimeProvider.System, loaded.Document.LoopRateHz);
        loop.Start();
        BridgeTestSupport.WaitFor(() => plugin.Steps >= 20, TimeSpan.FromSeconds(20), "20 steps");
        loop.Stop();
        var ticks = loop.TickCount;

        Assert.True(server.Stepping);
        Assert.InRange(plugin.Steps, 20, (ticks / 10) + 1);
        // A step whose reply misses its deadline is sent (the server counts it) but not acknowledged (the plug-in does
        // not). Under the whole suite's load the two counts once differed by one, most likely so: this test is about
        // the stepping cadence, so its calls get 10 s (not the 500 ms default), and a missed one is named.
        Assert.True(plugin.Steps == server.Steps, $"plug-in {plugin.Steps} steps, server {server.Steps}; last error: {plugin.LastError}");
    }

    [Fact]
    public void Joint_paths_default_to_the_urdf_names_and_overrides_are_checked()
    {
        var settings = new CoppeliaSimSettings { Model = "/Robot/", JointPaths = "left.elbow=/Other/elbow_l" };
        var map = JointPathMap.Build(BridgeTestSupport.Lb, settings, "sim");
        Assert.Equal(("right.shoulder_yaw", "/Robot/right_shoulder_yaw"), map[0]);
        Assert.Equal(("left.elbow", "/Other/elbow_l"), map.Single(m => m.Signal == "left.elbow"));

        var unknown = Assert.Throws<RobotControl.Plugins.Sdk.Settings.SettingsException>(() =>
            JointPathMap.Build(BridgeTestSupport.Lb, settings with { JointPaths = "left.knee=/x" }, "sim"));
        Assert.StartsWith("'sim': invalid settings: joint_paths: 'left.knee' is not a joint of LB-1.0", unknown.Message, StringComparison.Ordinal);
        var malformed = Assert.Throws<RobotControl.Plugins.Sdk.Settings.SettingsException>(() =>
            JointPathMap.Build(BridgeTestSupport.Lb, settings with { JointPaths = "left.elbow" }, "sim"));
        Assert.Equal("'sim': invalid settings: joint_paths: 'left.elbow' is not arm.joint=/path", malformed.Message);
    }

    // Holds the virtual run to no faster than real time, so the bridge (real time) sees a run of the stated length.
    private static void Pace(ControlLoop loop, Stopwatch wall)
    {
        var ahead = (loop.TickCount / loop.RateHz) - wall.Elapsed.TotalSeconds;
        if (ahead > 0.002)
        {
            Thread.Sleep(TimeSpan.FromSeconds(ahead));
        }
    }

    private static string Key(double[] values) => string.Join(",", values.Select(v => v.ToString("R", CultureInfo.InvariantCulture)));

    private enum KillPhase
    {
        Connecting,
        Killed,
        Restarted,
        Flowing,
    }
}
