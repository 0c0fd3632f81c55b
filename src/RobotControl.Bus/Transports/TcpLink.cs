using System.Net.Sockets;

namespace RobotControl.Bus.Transports;

/// <summary>A serial-over-network bridge (e.g. ser2net, socat TCP-LISTEN): bus bytes over a TCP stream.</summary>
public sealed class TcpLink : IByteLink
{
    private readonly Socket _socket;

    private TcpLink(Socket socket, string endpoint, int baud)
    {
        _socket = socket;
        Description = $"tcp {endpoint} (bus at {baud} baud)";
        BaudRate = baud;
    }

    /// <inheritdoc />
    public string Description { get; }

    /// <inheritdoc />
    public int BaudRate { get; }

    /// <summary>Connects to <paramref name="host"/>:<paramref name="port"/>; <paramref name="baud"/> is the bus speed behind the bridge.</summary>
    /// <exception cref="IOException">The connection fails.</exception>
    public static TcpLink Connect(string host, int port, int baud, TimeSpan connectTimeout)
    {
        ArgumentException.ThrowIfNullOrEmpty(host);
        var socket = new Socket(SocketType.Stream, ProtocolType.Tcp) { NoDelay = true };
        try
        {
            using var cts = new CancellationTokenSource(connectTimeout);
            socket.ConnectAsync(host, port, cts.Token).AsTask().GetAwaiter().GetResult();
        }
        catch (Exception ex) when (ex is SocketException or OperationCanceledException)
        {
            socket.Dispose();
            throw new IOException($"cannot connect to tcp {host}:{port}: {ex.Message}", ex);
        }

        return new TcpLink(socket, $"{host}:{port}", baud);
    }

    /// <inheritdoc />
    public void Write(ReadOnlySpan<byte> data)
    {
        while (!data.IsEmpty)
        {
            var n = _socket.Send(data);
            data = data[n..];
        }
    }

    /// <inheritdoc />
    public int Read(Span<byte> buffer, TimeSpan timeout)
    {
        if (!_socket.Poll(timeout, SelectMode.SelectRead))
        {
            return 0;
        }

        var n = _socket.Receive(buffer);
        return n > 0 ? n : throw new IOException($"{Description}: the bridge closed the connection");
    }

    /// <inheritdoc />
    public void DiscardInput()
    {
        Span<byte> scratch = stackalloc byte[256];
        while (_socket.Available > 0)
        {
            _socket.Receive(scratch);
        }
    }

    /// <inheritdoc />
    public void Dispose() => _socket.Dispose();
}
