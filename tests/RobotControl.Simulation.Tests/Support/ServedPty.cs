using RobotControl.Bus.Transports.Serial;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.TestSupport;

namespace RobotControl.Simulation.Tests.Support;

/// <summary>A virtual LB-1.0 served in real time on a fresh pty (for clients that open <see cref="SlavePath"/>).</summary>
internal sealed class ServedPty : IDisposable
{
    private readonly PseudoTerminal _pty = PseudoTerminal.Create();
    private readonly CancellationTokenSource _stop = new();
    private readonly Thread _server;

    public ServedPty()
    {
        Sim = new VirtualRobot(VirtualLb.Lb, new ManualTimeProvider());
        _server = new Thread(() => Sim.Serve(_pty, _stop.Token)) { IsBackground = true };
        _server.Start();
    }

    public VirtualRobot Sim { get; }

    public string SlavePath => _pty.SlavePath;

    public void Dispose()
    {
        _stop.Cancel();
        _server.Join();
        _stop.Dispose();
        Sim.Dispose();
        _pty.Dispose();
    }
}
