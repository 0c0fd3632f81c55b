using RobotControl.CoppeliaSim;
using RobotControl.Plugins.Sdk.Exchange;

namespace RobotControl.Plugins.CoppeliaSim;

/// <summary>
/// The bridge's network thread. It takes the newest joint command the loop published, sends it (one call per joint),
/// steps the simulation when stepping is on and enough ticks have passed, reads the joint positions back and
/// publishes them. When a call fails the connection counts as lost: <see cref="Connected"/> drops to false, the
/// socket is recreated and the session set up again after a back-off. The loop never waits on any of it.
/// </summary>
internal sealed class BridgeWorker : IDisposable
{
    private readonly CoppeliaSimSettings _settings;
    private readonly IReadOnlyList<string> _paths;
    private readonly LatestValue<JointFrame> _commands;
    private readonly LatestValue<JointFrame> _reports;
    private readonly ManualResetEventSlim _stop = new();
    private readonly Backoff _backoff = new(TimeSpan.FromMilliseconds(50), TimeSpan.FromSeconds(2));
    private readonly long[] _handles;
    private Thread? _thread;
    private volatile bool _connected;
    private long _lastTickSent = -1;
    private long _stepsDone;
    private long _firstTick = -1;
    private long _sessionSteps;
    private int _disposed;

    public BridgeWorker(CoppeliaSimSettings settings, IReadOnlyList<string> paths, LatestValue<JointFrame> commands, LatestValue<JointFrame> reports)
    {
        _settings = settings;
        _paths = paths;
        _commands = commands;
        _reports = reports;
        _handles = new long[paths.Count];
    }

    /// <summary>True while a session with the simulator is up.</summary>
    public bool Connected => _connected;

    /// <summary>Sessions set up so far (1 after the first connection, +1 per reconnection).</summary>
    public int Sessions { get; private set; }

    /// <summary>Simulation steps requested.</summary>
    public long Steps => Interlocked.Read(ref _stepsDone);

    /// <summary>The last error, for diagnostics.</summary>
    public string? LastError { get; private set; }

    public void Start()
    {
        _thread = new Thread(Run) { IsBackground = true, Name = "coppeliasim bridge" };
        _thread.Start();
    }

    public void Dispose()
    {
        if (Interlocked.Exchange(ref _disposed, 1) != 0)
        {
            return;
        }

        _stop.Set();
        _thread?.Join(TimeSpan.FromSeconds(5));
    }

    private void Run()
    {
        using var client = new RemoteApiClient(_settings.Endpoint, TimeSpan.FromMilliseconds(_settings.CallTimeoutMs));
        var sim = new SimApi(client);
        while (!_stop.IsSet)
        {
            try
            {
                if (!_connected)
                {
                    Setup(sim);
                }

                if (!Cycle(sim))
                {
                    _stop.Wait(1);
                }
            }
            catch (CoppeliaSimException ex)
            {
                _connected = false;
                LastError = ex.Message;
                client.Disconnect();
                _stop.Wait(_backoff.NextDelay());
            }
        }

        StopSimulation(sim);
    }

    private void Setup(SimApi sim)
    {
        sim.RequireSim();
        for (var i = 0; i < _paths.Count; i++)
        {
            _handles[i] = sim.GetObject(_paths[i], noError: true);
            if (_handles[i] < 0)
            {
                throw new CoppeliaSimServerException($"no object at {_paths[i]} in the scene");
            }
        }

        sim.SetStepping(_settings.Stepping);
        sim.StartSimulation();
        _backoff.Reset();
        _lastTickSent = -1;
        _firstTick = -1;
        _sessionSteps = 0;
        Sessions++;
        _connected = true;
    }

    // One exchange; false when the loop has published nothing new since the last one.
    private bool Cycle(SimApi sim)
    {
        if (!_commands.TryRead(out var command) || command.Tick == _lastTickSent)
        {
            return false;
        }

        for (var i = 0; i < _paths.Count; i++)
        {
            if (_settings.Mode == JointDriveMode.Dynamic)
            {
                sim.SetJointTargetPosition(_handles[i], command.Values[i]);
            }
            else
            {
                sim.SetJointPosition(_handles[i], command.Values[i]);
            }
        }

        _lastTickSent = command.Tick;
        if (_settings.Stepping)
        {
            // One step per ticks_per_step loop ticks since the session began; a slow simulator is not made to catch up.
            _firstTick = _firstTick < 0 ? command.Tick : _firstTick;
            var due = ((command.Tick - _firstTick) / _settings.TicksPerStep) + 1;
            if (due > _sessionSteps)
            {
                sim.Step();
                _sessionSteps = due;
                Interlocked.Increment(ref _stepsDone);
            }
        }

        var report = new JointFrame { Tick = command.Tick };
        for (var i = 0; i < _paths.Count; i++)
        {
            report.Values[i] = sim.GetJointPosition(_handles[i]);
        }

        _reports.Publish(report);
        return true;
    }

    private void StopSimulation(SimApi sim)
    {
        if (!_connected)
        {
            return;
        }

        try
        {
            sim.StopSimulation();
        }
        catch (CoppeliaSimException ex)
        {
            LastError = ex.Message;
        }

        _connected = false;
    }
}
