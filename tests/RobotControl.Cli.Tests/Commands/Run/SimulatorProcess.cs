using System.Text.RegularExpressions;
using RobotControl.Bus.Client;
using RobotControl.Bus.Transports;
using RobotControl.Hardware.Loading;
using RobotControl.Hardware.Model;

namespace RobotControl.Cli.Tests.Commands.Run;

/// <summary>
/// <c>robotctl bus-sim hardware/robots/lb-1.0.json --pty</c> in a process of its own (the real firmware behind a
/// pseudo-terminal), its <c>serial:</c> transport, and a client that reads its modules back independently of robotctl.
/// </summary>
internal sealed partial class SimulatorProcess : IDisposable
{
    private readonly RunProcess _process;

    public SimulatorProcess(TimeSpan patience)
    {
        _process = new RunProcess("bus-sim", RobotFile, "--pty");
        Transport = TransportOf().Match(_process.WaitFor("serving", patience)).Value;
    }

    /// <summary>The robot file served.</summary>
    public static string RobotFile => RunProcess.RepoFile("hardware", "robots", "lb-1.0.json");

    /// <summary>The robot served.</summary>
    public static RobotDefinition Robot => RobotLoader.Load(RobotFile);

    /// <summary>The simulator's transport, e.g. <c>serial:/dev/pts/3?baud=1000000</c>.</summary>
    public string Transport { get; }

    /// <summary>A client of its own on the pty, with a margin a loaded machine allows.</summary>
    public BusClient ReadBack() =>
        new(LinkFactory.Open(Transport), TimeProvider.System, new BusClientOptions { ResponseMargin = TimeSpan.FromMilliseconds(50) });

    public void Dispose() => _process.Dispose();

    [GeneratedRegex(@"serial:\S+")]
    private static partial Regex TransportOf();
}
