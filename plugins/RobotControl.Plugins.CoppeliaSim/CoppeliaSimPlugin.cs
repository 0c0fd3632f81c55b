using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Exchange;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.CoppeliaSim;

/// <summary>
/// Drives a robot model in CoppeliaSim over the ZeroMQ remote API. Inputs: one per joint of every arm
/// (<c>right.elbow</c>, rad, in the arm's own model, as the robot node takes them). Outputs: the positions the
/// simulator reports (<c>right.elbow.position</c>) and <c>connected</c> (1 while a session is up). The network runs
/// on the bridge's own thread; <see cref="Tick"/> only publishes the commands and copies the latest report, so a slow
/// or lost simulator never delays the loop: the outputs hold their last values, <c>connected</c> goes to 0, and
/// the bridge reconnects with back-off.
/// </summary>
[PluginType("coppeliasim", Description = "CoppeliaSim bridge: joint commands to the simulator, joint positions back (ZeroMQ remote API).")]
public sealed class CoppeliaSimPlugin : Plugin<CoppeliaSimSettings>, IDisposable
{
    private readonly InputPort[] _inputs;
    private readonly OutputPort[] _positions;
    private readonly OutputPort _connected;
    private readonly LatestValue<JointFrame> _commands = new();
    private readonly LatestValue<JointFrame> _reports = new();
    private readonly BridgeWorker _worker;
    private JointFrame _command;
    private long _lastReportTick = -1;

    /// <summary>Creates the bridge for the graph's robot.</summary>
    public CoppeliaSimPlugin(CoppeliaSimSettings settings, PluginContext context)
        : base(settings, context)
    {
        ArgumentNullException.ThrowIfNull(context);
        var map = JointPathMap.Build(context.RequireRobot(), Settings, context.InstanceName);
        _inputs = [.. map.Select(m => DeclareInput(m.Signal, "rad", $"{m.Signal} command, sent to {m.Path}"))];
        _positions = [.. map.Select(m => DeclareOutput($"{m.Signal}.position", SafeValue.HoldLastFinite, "rad", $"{m.Signal} position the simulator reports"))];
        _connected = DeclareOutput("connected", SafeValue.Zero, "", "1 while a session with the simulator is up");
        JointPaths = [.. map.Select(m => m.Path)];
        _worker = new BridgeWorker(Settings, JointPaths, _commands, _reports);
    }

    /// <summary>Scene path of each joint, in port order.</summary>
    public IReadOnlyList<string> JointPaths { get; }

    /// <summary>True while a session with the simulator is up.</summary>
    public bool IsConnected => _worker.Connected;

    /// <summary>Sessions set up (reconnections + 1).</summary>
    public int Sessions => _worker.Sessions;

    /// <summary>Simulation steps requested in stepped mode.</summary>
    public long Steps => _worker.Steps;

    /// <summary>The last communication error, or null.</summary>
    public string? LastError => _worker.LastError;

    /// <summary>Reports received from the simulator.</summary>
    public long Reports => _reports.PublishedCount;

    /// <summary>The loop tick of the command the latest report answered (-1 before the first).</summary>
    public long LastReportTick => _lastReportTick;

    /// <inheritdoc />
    public override void Start(in TickContext context) => _worker.Start();

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        for (var i = 0; i < _inputs.Length; i++)
        {
            _command.Values[i] = Read(_inputs[i]);
        }

        _command.Tick = context.Index;
        _commands.Publish(_command);
        if (_reports.TryRead(out var report))
        {
            _lastReportTick = report.Tick;
            for (var i = 0; i < _positions.Length; i++)
            {
                Write(_positions[i], report.Values[i]);
            }
        }

        Write(_connected, _worker.Connected ? 1 : 0);
    }

    /// <inheritdoc />
    public override void Stop() => _worker.Dispose();

    /// <summary>Stops the bridge thread (as <see cref="Stop"/>).</summary>
    public void Dispose() => _worker.Dispose();
}
