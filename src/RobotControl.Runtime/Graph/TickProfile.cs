using System.Diagnostics;
using RobotControl.Plugins.Sdk;

namespace RobotControl.Runtime.Graph;

/// <summary>
/// Where a tick's time goes, as the loop's thread writes it instance by instance (<see cref="Stopwatch"/> time: real
/// time, also on a virtual clock): the instance in its tick now and since when, and the slowest instance of the last
/// complete tick with its cost. Read from any thread: the safety supervisor names the plug-in a late loop waits for,
/// a stop names the plug-in a loop thread that will not end is stuck in. Writing allocates nothing, and neither does
/// naming (each instance's description is built once).
/// </summary>
public sealed class TickProfile
{
    private readonly string[] _inTick;
    private readonly string[] _slowest;
    private int _current = -1;
    private long _since;
    private int _slowestIndex = -1;
    private long _slowestCost;

    internal TickProfile(IReadOnlyList<Plugin> order)
    {
        _inTick = [.. order.Select(p => $"plug-in '{p.Name}' ({p.GetType().Name}), in its tick")];
        _slowest = [.. order.Select(p => $"plug-in '{p.Name}' ({p.GetType().Name}), the slowest of the last tick")];
    }

    /// <summary>The loop's thread: instance <paramref name="index"/> starts its tick at <paramref name="timestamp"/>.</summary>
    internal void Enter(int index, long timestamp)
    {
        Volatile.Write(ref _current, -1);
        Volatile.Write(ref _since, timestamp);
        Volatile.Write(ref _current, index);
    }

    /// <summary>The loop's thread: no instance is in its tick.</summary>
    internal void Leave() => Volatile.Write(ref _current, -1);

    /// <summary>The loop's thread: a tick is complete; <paramref name="slowest"/> took <paramref name="cost"/> (Stopwatch ticks).</summary>
    internal void Complete(int slowest, long cost)
    {
        Volatile.Write(ref _slowestIndex, -1);
        Volatile.Write(ref _slowestCost, cost);
        Volatile.Write(ref _slowestIndex, slowest);
    }

    /// <summary>The instance in its tick now and how long it has been in it (ms), or null between ticks.</summary>
    public (string Name, double Ms)? InTick()
    {
        var index = Volatile.Read(ref _current);
        if (index < 0)
        {
            return null;
        }

        var since = Volatile.Read(ref _since);
        return Volatile.Read(ref _current) == index ? (_inTick[index], Ms(Stopwatch.GetTimestamp() - since)) : null;
    }

    /// <summary>The slowest instance of the last complete tick and its cost (ms), or null before the first.</summary>
    public (string Name, double Ms)? SlowestOfLastTick()
    {
        var index = Volatile.Read(ref _slowestIndex);
        return index < 0 ? null : (_slowest[index], Ms(Volatile.Read(ref _slowestCost)));
    }

    /// <summary>
    /// The plug-in a late loop waits for, in words (built once per instance: nothing allocated): the one in its tick
    /// now, else the slowest of the last tick when it took <paramref name="overMs"/> or more; else <c>loop</c> (the
    /// loop's thread is between ticks: not scheduled, or not running).
    /// </summary>
    public string Culprit(double overMs) =>
        InTick()?.Name ?? (SlowestOfLastTick() is { } slowest && slowest.Ms >= overMs ? slowest.Name : "loop");

    private static double Ms(long stopwatchTicks) => stopwatchTicks * 1e3 / Stopwatch.Frequency;
}
