using System.Diagnostics;
using System.Globalization;
using System.Net;
using System.Net.Sockets;
using System.Text;

namespace RobotControl.TestSupport.Nats;

/// <summary>
/// A real <c>nats-server</c> (Debian's, installed by tools/bootstrap.sh) on a free loopback port, for the link tests:
/// started and waited for until it greets a client, killed by its PID, and restarted on the same port.
/// </summary>
public sealed class NatsServer : IDisposable
{
    private static readonly TimeSpan StartTimeout = TimeSpan.FromSeconds(20);
    private readonly string _authArguments;
    private Process? _process;

    private NatsServer(string authArguments)
    {
        _authArguments = authArguments;
        Port = FreePort();
    }

    /// <summary>The port it listens on (the same after a restart).</summary>
    public int Port { get; }

    /// <summary>Its URL, <c>nats://127.0.0.1:port</c>.</summary>
    public string Url => $"nats://127.0.0.1:{Port.ToString(CultureInfo.InvariantCulture)}";

    /// <summary>The PID of the running server (0 when it is not running).</summary>
    public int Pid => _process is { HasExited: false } p ? p.Id : 0;

    /// <summary>Starts a server with no authentication.</summary>
    public static NatsServer Start() => Started(new NatsServer(""));

    /// <summary>Starts a server that wants this user and password.</summary>
    public static NatsServer StartWithUser(string user, string password) => Started(new NatsServer($"--user {user} --pass {password}"));

    /// <summary>Kills the server (SIGKILL to its PID: no goodbye to the clients) and waits until it is gone.</summary>
    public void Kill()
    {
        if (_process is null)
        {
            return;
        }

        using (var byPid = Process.GetProcessById(_process.Id))
        {
            byPid.Kill();
            byPid.WaitForExit();
        }

        _process.Dispose();
        _process = null;
    }

    /// <summary>Starts the server again on the same port.</summary>
    public void Restart()
    {
        Kill();
        Launch();
    }

    public void Dispose() => Kill();

    private static NatsServer Started(NatsServer server)
    {
        server.Launch();
        return server;
    }

    private void Launch()
    {
        var info = new ProcessStartInfo("nats-server", $"-a 127.0.0.1 -p {Port.ToString(CultureInfo.InvariantCulture)} {_authArguments}")
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        _process = Process.Start(info) ?? throw new InvalidOperationException("nats-server did not start (run tools/bootstrap.sh)");
        _process.OutputDataReceived += (_, _) => { };
        _process.ErrorDataReceived += (_, _) => { };
        _process.BeginOutputReadLine();
        _process.BeginErrorReadLine();
        WaitUntilServing();
    }

    // Until a client connecting gets the server's INFO line; a server that cannot start (port taken) fails here.
    private void WaitUntilServing()
    {
        var end = DateTime.UtcNow + StartTimeout;
        while (true)
        {
            if (_process!.HasExited)
            {
                throw new InvalidOperationException($"nats-server on port {Port} exited with code {_process.ExitCode}");
            }

            try
            {
                using var client = new TcpClient();
                client.Connect(IPAddress.Loopback, Port);
                var buffer = new byte[4];
                using var stream = client.GetStream();
                stream.ReadTimeout = 2000;
                if (stream.ReadAtLeast(buffer, 4, throwOnEndOfStream: false) == 4 && Encoding.ASCII.GetString(buffer) == "INFO")
                {
                    return;
                }
            }
            catch (SocketException) when (DateTime.UtcNow < end)
            {
            }
            catch (IOException) when (DateTime.UtcNow < end)
            {
            }

            if (DateTime.UtcNow > end)
            {
                throw new TimeoutException($"nats-server on port {Port} did not accept a connection within {StartTimeout.TotalSeconds} s");
            }

            Thread.Sleep(20);
        }
    }

    private static int FreePort()
    {
        using var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        return ((IPEndPoint)listener.LocalEndpoint).Port;
    }
}
