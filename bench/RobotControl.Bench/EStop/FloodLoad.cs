using System.Diagnostics;

namespace RobotControl.Bench.EStop;

/// <summary>
/// A flood of API reads while the stops run: <c>GET /api/status</c> and <c>GET /api/controllers</c> in turn from
/// several HttpClients (one connection each), paced together to a target rate (a client that falls more than 50 ms
/// behind its schedule drops the backlog rather than bursting). Counts what was sent and answered.
/// </summary>
internal sealed class FloodLoad : IAsyncDisposable
{
    private static readonly string[] Paths = ["api/status", "api/controllers"];
    private readonly CancellationTokenSource _stop = new();
    private readonly Task[] _workers;
    private readonly long _start = Stopwatch.GetTimestamp();
    private long _answered;
    private long _failed;

    private FloodLoad(Uri baseUrl, string token, double ratePerSecond, int clients)
    {
        var period = clients / ratePerSecond;
        _workers = [.. Enumerable.Range(0, clients).Select(i => Task.Run(() => Worker(baseUrl, token, period, i)))];
    }

    /// <summary>Starts <paramref name="clients"/> clients sending <paramref name="ratePerSecond"/> requests per second together.</summary>
    public static FloodLoad Start(Uri baseUrl, string token, double ratePerSecond, int clients) => new(baseUrl, token, ratePerSecond, clients);

    /// <summary>Requests answered per second since the start.</summary>
    public double AnsweredPerSecond => Interlocked.Read(ref _answered) / Stopwatch.GetElapsedTime(_start).TotalSeconds;

    /// <summary>Requests that failed or were not answered 200.</summary>
    public long Failed => Interlocked.Read(ref _failed);

    private async Task Worker(Uri baseUrl, string token, double periodSeconds, int index)
    {
        using var client = new HttpClient { BaseAddress = baseUrl };
        client.DefaultRequestHeaders.Authorization = new System.Net.Http.Headers.AuthenticationHeaderValue("Bearer", token);
        client.DefaultRequestHeaders.Add("X-Console-Client", $"bench-flood-{index}");
        var period = (long)(periodSeconds * Stopwatch.Frequency);
        var next = Stopwatch.GetTimestamp() + (period * index / _workers.Length);
        var behind = Stopwatch.Frequency / 20;
        for (var n = index; !_stop.IsCancellationRequested; n++)
        {
            var wait = next - Stopwatch.GetTimestamp();
            if (wait > 0)
            {
                await Task.Delay(TimeSpan.FromSeconds(wait / (double)Stopwatch.Frequency)).ConfigureAwait(false);
            }
            else if (-wait > behind)
            {
                next = Stopwatch.GetTimestamp();
            }

            next += period;
            try
            {
                using var response = await client.GetAsync(Paths[n % Paths.Length], _stop.Token).ConfigureAwait(false);
                _ = await response.Content.ReadAsByteArrayAsync(_stop.Token).ConfigureAwait(false);
                Interlocked.Increment(ref response.IsSuccessStatusCode ? ref _answered : ref _failed);
            }
            catch (Exception ex) when (ex is HttpRequestException or OperationCanceledException)
            {
                if (!_stop.IsCancellationRequested)
                {
                    Interlocked.Increment(ref _failed);
                }
            }
        }
    }

    public async ValueTask DisposeAsync()
    {
        await _stop.CancelAsync().ConfigureAwait(false);
        await Task.WhenAll(_workers).ConfigureAwait(false);
        _stop.Dispose();
    }
}
