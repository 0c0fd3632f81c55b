using System.Diagnostics;
using System.Globalization;
using System.IO.Ports;
using System.Text.Json;
using RobotControl.Bench.Ik;
using RobotControl.Bus.Transports.Serial;
using RobotControl.Host.Session;

namespace RobotControl.Bench.Serial;

/// <summary>
/// <c>serial [--transactions n] [--out file.json]</c>: request/reply transactions (8 bytes out, 11 back, answered by an
/// echo thread on a pty master) through <see cref="SerialLink"/> and, for comparison, through
/// <c>SerialPort.BaseStream</c> (the design the link does not use); plus reads that time out. Reports latency,
/// bytes allocated and CPU: why the link moves bytes on the port's descriptor itself.
/// </summary>
internal sealed class SerialBenchCommand : IBenchCommand
{
    private static readonly JsonSerializerOptions JsonOptions = new() { WriteIndented = true };
    private static readonly byte[] Request = new byte[8];
    private static readonly byte[] Reply = new byte[11];

    public string Name => "serial";

    public string Description => "Serial link on a pty: transaction latency, allocation and CPU vs SerialPort.BaseStream; timed-out reads.";

    public int Run(string[] args)
    {
        var transactions = int.Parse(BenchArgs.Value(args, "--transactions") ?? "2000", CultureInfo.InvariantCulture);
        var outFile = BenchArgs.Value(args, "--out");
        var rx = new byte[64];
        var results = new List<Result>();

        using (var pty = PseudoTerminal.Create())
        using (var echo = new Echo(pty))
        using (var link = SerialLink.Open(pty.SlavePath, 1_000_000))
        {
            results.Add(Transactions("SerialLink", transactions, () =>
            {
                link.Write(Request);
                for (var got = 0; got < Reply.Length;)
                {
                    var n = link.Read(rx.AsSpan(got), TimeSpan.FromMilliseconds(500));
                    got += n > 0 ? n : throw new TimeoutException("no reply through SerialLink");
                }
            }));
            results.Add(Timeouts("SerialLink.Read, 500 us timeout", 1000, () => link.Read(rx, TimeSpan.FromMicroseconds(500)) == 0));
        }

        using (var pty = PseudoTerminal.Create())
        using (var echo = new Echo(pty))
        using (var port = new SerialPort(pty.SlavePath, 1_000_000, Parity.None, 8, StopBits.One) { Handshake = Handshake.None })
        {
            port.Open();
            var stream = port.BaseStream;
            results.Add(Transactions("SerialPort.BaseStream (read when BytesToRead > 0)", transactions, () =>
            {
                stream.Write(Request);
                var start = Stopwatch.GetTimestamp();
                for (var got = 0; got < Reply.Length;)
                {
                    if (port.BytesToRead > 0)
                    {
                        got += stream.Read(rx.AsSpan(got));
                    }
                    else if (Stopwatch.GetElapsedTime(start) > TimeSpan.FromMilliseconds(500))
                    {
                        throw new TimeoutException("no reply through SerialPort");
                    }
                    else
                    {
                        Thread.Yield();
                    }
                }
            }));
            port.ReadTimeout = 1;
            results.Add(Timeouts("SerialPort.BaseStream.Read, ReadTimeout 1 ms", 50, () =>
            {
                try
                {
                    _ = stream.Read(rx); // only the timeout matters here
                    return false;
                }
                catch (TimeoutException)
                {
                    return true;
                }
            }));
        }

        Console.WriteLine("what                                                 count  median us  p99 us  B/op (thread)  B/op (all)  thread CPU");
        foreach (var r in results)
        {
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"{r.What,-52} {r.Count,5}  {r.MedianUs,9:F0}  {r.P99Us,6:F0}  {r.BytesPerOpThread,13:F1}  {r.BytesPerOpAll,10:F1}  {r.ThreadCpuShare * 100,8:F1} %"));
        }

        if (outFile is not null)
        {
            File.WriteAllText(outFile, JsonSerializer.Serialize(results, JsonOptions));
        }

        return 0;
    }

    private static Result Transactions(string what, int count, Action transaction)
    {
        for (var i = 0; i < 200; i++)
        {
            transaction(); // JIT and first-use allocations
        }

        return Time(what, count, () =>
        {
            transaction();
            return true;
        });
    }

    private static Result Timeouts(string what, int count, Func<bool> timedOut)
    {
        timedOut();
        var result = Time(what, count, timedOut);
        return result.Failures == 0 ? result : throw new InvalidOperationException($"{what}: {result.Failures} of {count} reads did not time out");
    }

    private static Result Time(string what, int count, Func<bool> op)
    {
        var latencies = new double[count];
        var failures = 0;
        var cpu0 = ThreadCpuClock.NowUs();
        var wall = Stopwatch.StartNew();
        var thread0 = GC.GetAllocatedBytesForCurrentThread();
        var all0 = GC.GetTotalAllocatedBytes(precise: true);
        for (var i = 0; i < count; i++)
        {
            var start = Stopwatch.GetTimestamp();
            failures += op() ? 0 : 1;
            latencies[i] = Stopwatch.GetElapsedTime(start).TotalMicroseconds;
        }

        var thread = GC.GetAllocatedBytesForCurrentThread() - thread0;
        var all = GC.GetTotalAllocatedBytes(precise: true) - all0;
        var cpu = ThreadCpuClock.NowUs() - cpu0;
        var wallUs = wall.Elapsed.TotalMicroseconds;
        Array.Sort(latencies);
        return new Result(what, count, failures, latencies[count / 2], latencies[Math.Min(count - 1, count * 99 / 100)], (double)thread / count, (double)all / count, cpu / wallUs);
    }


    private sealed record Result(string What, int Count, int Failures, double MedianUs, double P99Us, double BytesPerOpThread, double BytesPerOpAll, double ThreadCpuShare);

    /// <summary>Answers every 8 bytes from the host with an 11-byte reply, like one module on the bus.</summary>
    private sealed class Echo : IDisposable
    {
        private readonly Thread _thread;
        private volatile bool _stop;

        public Echo(PseudoTerminal pty)
        {
            _thread = new Thread(() =>
            {
                var buffer = new byte[64];
                var have = 0;
                while (!_stop)
                {
                    have += pty.Read(buffer.AsSpan(have), TimeSpan.FromMilliseconds(50));
                    for (; have >= Request.Length; have -= Request.Length)
                    {
                        pty.Write(Reply);
                    }
                }
            }) { IsBackground = true, Name = "pty echo" };
            _thread.Start();
        }

        public void Dispose()
        {
            _stop = true;
            _thread.Join();
        }
    }
}
