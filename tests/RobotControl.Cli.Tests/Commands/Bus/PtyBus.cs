using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Transports.Serial;
using RobotControl.Definitions.Loading;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;

namespace RobotControl.Cli.Tests.Commands.Bus;

/// <summary>
/// A virtual robot (LB-1.0, real firmware) serving its bus on a pseudo-terminal in real time, as <c>robotctl bus-sim
/// --pty</c> does: commands reach it through <c>serial:</c> like a real adapter, and its modules keep what was written
/// between commands, so a test can read the table back.
/// </summary>
internal sealed class PtyBus : IDisposable
{
    /// <summary>The tests with a real-time bus run one at a time (the simulation keeps up with the wire only on a free core).</summary>
    public const string Collection = "pty bus";

    private readonly VirtualRobot _sim;
    private readonly PseudoTerminal _pty;
    private readonly CancellationTokenSource _stop = new();
    private readonly Thread _thread;

    /// <param name="serve">False: nothing answers on the pty.</param>
    /// <param name="simulatedRobotFile">The robot the bus simulates, when it differs from the robot file the commands get.</param>
    public PtyBus(bool serve = true, string? simulatedRobotFile = null)
    {
        RobotFile = Cli.RepoFile("hardware/robots/lb-1.0.json");
        _sim = new VirtualRobot(RobotLoader.Load(simulatedRobotFile ?? RobotFile), new ManualTimeProvider(), new VirtualRobotOptions { Seed = 1 });
        _pty = PseudoTerminal.Create();
        _thread = new Thread(() => _sim.Serve(_pty, _stop.Token)) { IsBackground = true, Name = "pty bus" };
        if (serve)
        {
            _thread.Start();
        }
    }

    public string RobotFile { get; }

    public string SlavePath => _pty.SlavePath;

    public string Transport => $"serial:{_pty.SlavePath}";

    /// <summary>Runs robotctl <paramref name="command"/> on this bus (transport, --robot and a reply margin for a loaded machine added).</summary>
    public (int Code, string Output, string Error) Run(string command, params string[] args)
    {
        var words = command.Split(' ');
        string[] margin = args.Contains("--margin-ms") ? [] : ["--margin-ms", "100"];
        return Cli.Run([.. words, Transport, "--robot", RobotFile, .. margin, .. args]);
    }

    /// <summary>Runs robotctl <paramref name="command"/> on this bus opened at <paramref name="baud"/> (as <see cref="Run"/> does).</summary>
    public (int Code, string Output, string Error) RunAt(int baud, string command, params string[] args)
    {
        var words = command.Split(' ');
        string[] margin = args.Contains("--margin-ms") ? [] : ["--margin-ms", "100"];
        return Cli.Run([.. words, $"{Transport}?baud={baud}", "--robot", RobotFile, .. margin, .. args]);
    }

    /// <summary>The value module <paramref name="id"/> holds in <paramref name="field"/>[<paramref name="motor"/>], read from its control table (at <paramref name="baud"/>).</summary>
    public long Read(byte id, string field, int motor, int baud = 1_000_000)
    {
        var f = ControlTable.Firmware[field];
        using var client = Client(baud);
        var bytes = new byte[f.Size];
        var reply = client.Read(id, f.At(motor), bytes);
        return reply.Succeeded ? f.Decode(bytes) : throw new IOException($"module {id}: reading {field}[{motor}] failed ({reply.Outcome})");
    }

    /// <summary>Writes <paramref name="value"/> into module <paramref name="id"/>'s module-wide <paramref name="field"/> at <paramref name="baud"/> (acknowledged).</summary>
    public void Write(byte id, string field, long value, int baud = 1_000_000)
    {
        var f = ControlTable.Firmware[field];
        using var client = Client(baud);
        var bytes = new byte[f.Size];
        f.Encode(value, bytes);
        var reply = client.Write(id, f.At(0), bytes);
        Assert.True(reply.Succeeded, $"module {id}: writing {field} = {value} at {baud} baud: {reply}");
    }

    /// <summary>Whether module <paramref name="id"/> answers a ping at <paramref name="baud"/>.</summary>
    public bool Answers(byte id, int baud)
    {
        using var client = Client(baud);
        return client.Ping(id, out _).Succeeded;
    }

    private BusClient Client(int baud) =>
        new(SerialLink.Open(SlavePath, baud), TimeProvider.System, new BusClientOptions { ResponseMargin = TimeSpan.FromMilliseconds(100) });

    public void Dispose()
    {
        _stop.Cancel();
        if (_thread.IsAlive)
        {
            _thread.Join();
        }

        _pty.Dispose();
        _sim.Dispose();
        _stop.Dispose();
    }
}
