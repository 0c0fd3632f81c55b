using System.Text.RegularExpressions;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Transports;
using RobotControl.Definitions.Loading;
using RobotControl.Definitions.Model;

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

    /// <summary>
    /// Reads every module back over the pty, independently of robotctl: each answers with torque off on every channel
    /// (and, unless <paramref name="latchedAllowed"/>, with no hardware error latched).
    /// </summary>
    public void AssertTorqueOff(bool latchedAllowed = false)
    {
        var table = ControlTable.Firmware;
        var torque = table["torque_enable"];
        var status = table["hardware_error_status"];
        using var client = ReadBack();
        var channels = new byte[((torque.Count - 1) * torque.Stride) + torque.Size];
        var error = new byte[1];
        foreach (var m in Robot.Modules.Modules)
        {
            Assert.True(client.Read(m.Id, torque.At(0), channels).Succeeded, $"module {m.Id} did not answer");
            Assert.All(channels, b => Assert.Equal(0, b));
            Assert.True(client.Read(m.Id, status.At(0), error).Outcome == ReplyOutcome.Ok);
            Assert.True(latchedAllowed || error[0] == 0, $"module {m.Id} latched error {error[0]}");
        }
    }

    /// <summary>Kills the simulator outright (SIGKILL), as an unplugged adapter ends the link: the pty's other end hangs up.</summary>
    public void Kill() => _process.Signal("KILL");

    public void Dispose() => _process.Dispose();

    [GeneratedRegex(@"serial:\S+")]
    private static partial Regex TransportOf();
}
