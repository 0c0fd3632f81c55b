using System.Collections.Concurrent;
using NetMQ;
using NetMQ.Sockets;
using RobotControl.CoppeliaSim.Protocol;

namespace RobotControl.CoppeliaSim.Tests;

/// <summary>
/// A stand-in for CoppeliaSim's ZeroMQ remote API server: a REP socket speaking CBOR, a scene of named joints, the
/// calls the bridge makes, <c>_*wait*_</c> replies during <c>sim.step</c>, <c>_*repeat*_</c> on demand, error replies,
/// a callback round, and a server that stops answering or is killed and restarted on the same port.
/// </summary>
internal sealed class FakeCoppeliaSim : IDisposable
{
    private readonly Dictionary<string, long> _handles = new(StringComparer.Ordinal);
    private readonly Dictionary<long, double> _positions = [];
    private readonly Dictionary<long, double> _targets = [];
    private readonly object _gate = new();
    private Thread? _thread;
    private volatile bool _running;
    private volatile bool _silent;
    private int _repeatNext;
    private readonly long _firstHandle = 10;

    public FakeCoppeliaSim(IEnumerable<string> jointPaths, int port = 0)
    {
        foreach (var path in jointPaths)
        {
            var handle = _firstHandle + _handles.Count;
            _handles[path] = handle;
            _positions[handle] = 0;
        }

        Port = port;
        Start();
    }

    public int Port { get; private set; }

    public string Endpoint => $"tcp://127.0.0.1:{Port}";

    /// <summary>Wait replies sent before each sim.step completes.</summary>
    public int WaitsPerStep { get; set; } = 2;

    public long Steps => Interlocked.Read(ref _steps);

    public bool Stepping { get; private set; }

    public bool SimulationRunning { get; private set; }

    public ConcurrentQueue<(string Func, IReadOnlyList<object?> Args)> Requests { get; } = new();

    public ConcurrentQueue<IReadOnlyDictionary<string, object?>> RawRequests { get; } = new();

    private long _steps;

    /// <summary>Answers <c>_*repeat*_</c> to the next <paramref name="count"/> requests.</summary>
    public void RepeatNext(int count) => Interlocked.Exchange(ref _repeatNext, count);

    /// <summary>From now on receives requests but never answers.</summary>
    public void StopAnswering() => _silent = true;

    public double Position(string path)
    {
        lock (_gate)
        {
            return _positions[_handles[path]];
        }
    }

    public void SetPosition(string path, double value)
    {
        lock (_gate)
        {
            _positions[_handles[path]] = value;
        }
    }

    /// <summary>Closes the socket: the server is gone.</summary>
    public void Kill()
    {
        _running = false;
        _thread?.Join();
        _thread = null;
    }

    /// <summary>Binds again on the same port and answers.</summary>
    public void Start()
    {
        _silent = false;
        _running = true;
        using var ready = new ManualResetEventSlim();
        _thread = new Thread(() => Serve(ready)) { IsBackground = true, Name = "fake CoppeliaSim" };
        _thread.Start();
        ready.Wait();
    }

    public void Dispose() => Kill();

    private void Serve(ManualResetEventSlim ready)
    {
        using var socket = new ResponseSocket();
        socket.Options.Linger = TimeSpan.Zero;
        if (Port == 0)
        {
            Port = socket.BindRandomPort("tcp://127.0.0.1");
        }
        else
        {
            socket.Bind(Endpoint);
        }

        ready.Set();
        Dictionary<string, object?>? pending = null;
        var waitsLeft = 0;
        while (_running)
        {
            if (!socket.TryReceiveFrameBytes(TimeSpan.FromMilliseconds(20), out var bytes))
            {
                continue;
            }

            var request = (IReadOnlyDictionary<string, object?>)RemoteApiCodec.Decode(bytes)!;
            RawRequests.Enqueue(request);
            if (_silent)
            {
                while (_running)
                {
                    Thread.Sleep(5); // a hung server: the REP socket never answers
                }

                break;
            }

            var func = (string)request["func"]!;
            var args = (IReadOnlyList<object?>)request["args"]!;
            Requests.Enqueue((func, args));
            if (Interlocked.Decrement(ref _repeatNext) >= 0)
            {
                socket.SendFrame(Reply("func", RemoteApiWords.Repeat, "args", new List<object?>()));
                continue;
            }

            Interlocked.Exchange(ref _repeatNext, 0);
            if (func == RemoteApiWords.Executed && pending is not null)
            {
                if (waitsLeft-- > 0)
                {
                    socket.SendFrame(Reply("func", RemoteApiWords.Wait, "args", new List<object?>()));
                    continue;
                }

                var done = pending;
                pending = null;
                socket.SendFrame(Reply("ret", done["ret"]));
                continue;
            }

            if (func == "sim.step" && WaitsPerStep > 0)
            {
                DoStep();
                pending = new Dictionary<string, object?> { ["ret"] = new List<object?>() };
                waitsLeft = WaitsPerStep - 1;
                socket.SendFrame(Reply("func", RemoteApiWords.Wait, "args", new List<object?>()));
                continue;
            }

            if (func == "test.end")
            {
                socket.SendFrame(Reply("func", RemoteApiWords.End, "args", new List<object?>()));
                continue;
            }

            if (func == "test.callback")
            {
                pending = new Dictionary<string, object?> { ["ret"] = new List<object?> { "called back" } };
                waitsLeft = 0;
                socket.SendFrame(Reply("func", "myCallback", "args", new List<object?> { 21L }));
                continue;
            }

            socket.SendFrame(Handle(func, args));
        }
    }

    private byte[] Handle(string func, IReadOnlyList<object?> args)
    {
        lock (_gate)
        {
            switch (func)
            {
                case "zmqRemoteApi.require":
                    return Ok();
                case "sim.getObject":
                    var path = (string)args[0]!;
                    if (_handles.TryGetValue(path, out var handle))
                    {
                        return Ok(handle);
                    }

                    return args.Count > 1 && args[1] is IReadOnlyDictionary<string, object?> o && o.TryGetValue("noError", out var ne) && ne is true
                        ? Ok(-1L)
                        : Reply("err", $"Object does not exist._=NL=_{RemoteApiWords.EscapedTab}(in function 'sim.getObject')");
                case "sim.setJointPosition":
                    _positions[Handle(args)] = Convert.ToDouble(args[1], System.Globalization.CultureInfo.InvariantCulture);
                    return Ok();
                case "sim.setJointTargetPosition":
                    _targets[Handle(args)] = Convert.ToDouble(args[1], System.Globalization.CultureInfo.InvariantCulture);
                    return Ok();
                case "sim.getJointPosition":
                    return Ok(_positions[Handle(args)]);
                case "sim.setStepping":
                    Stepping = (bool)args[0]!;
                    return Ok(0L);
                case "sim.step":
                    DoStep();
                    return Ok();
                case "sim.startSimulation":
                    SimulationRunning = true;
                    return Ok(1L);
                case "sim.stopSimulation":
                    SimulationRunning = false;
                    return Ok(1L);
                default:
                    return Reply("err", $"unknown function {func}");
            }
        }
    }

    private long Handle(IReadOnlyList<object?> args)
    {
        var handle = Convert.ToInt64(args[0], System.Globalization.CultureInfo.InvariantCulture);
        return _positions.ContainsKey(handle) ? handle : throw new InvalidOperationException($"no joint {handle}");
    }

    // Dynamic mode: the joint controllers reach their targets within one step.
    private void DoStep()
    {
        lock (_gate)
        {
            foreach (var (handle, target) in _targets)
            {
                _positions[handle] = target;
            }
        }

        Interlocked.Increment(ref _steps);
    }

    private static byte[] Ok(params object?[] ret) => Reply("ret", ret.ToList());

    private static byte[] Reply(params object?[] pairs)
    {
        var writer = new System.Formats.Cbor.CborWriter();
        writer.WriteStartMap(pairs.Length / 2);
        for (var i = 0; i < pairs.Length; i += 2)
        {
            writer.WriteTextString((string)pairs[i]!);
            RemoteApiCodec.WriteValue(writer, pairs[i + 1]);
        }

        writer.WriteEndMap();
        return writer.Encode();
    }
}
