using System.Collections.Concurrent;
using RobotControl.Modules;
using RobotControl.Robot.Bus;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// The modules' parameters as the bus page shows them, in the units table's units (<see cref="MotorParameter"/>):
/// read once per module between bus cycles, one module at a time, and kept as last read or written back.
/// <para>
/// Written by: the values, the bus's owner (reads and written-back writes, between cycles); the queue of modules
/// waiting, the session's start and a discovery (the bus's owner) add to it, the status thread takes from it, a failed
/// read puts its module back; the read under way, the status thread; the tries, the read's continuation (one read at a
/// time). The status thread reads the values for its snapshots.
/// </para>
/// </summary>
internal sealed class ModuleParameters(BusRobot bus, CommandQueue commands, SessionEvents events)
{
    /// <summary>How many times a module's parameters are tried before they are left unknown.</summary>
    private const int ReadTries = 5;

    private readonly ConcurrentDictionary<(int Module, int Channel, string Key), double> _values = [];
    private readonly ConcurrentQueue<RobotController> _waiting = new();
    private readonly Dictionary<int, int> _tries = [];
    private Task<CommandResult>? _reading;

    /// <summary>Queues every module present for a read (on the status thread's next turns).</summary>
    public void QueuePresentModules()
    {
        foreach (var c in bus.Controllers.Where(c => c.Present))
        {
            _waiting.Enqueue(c);
        }
    }

    /// <summary>
    /// The status thread's turn: when no read is under way, the next module waiting has its parameters read between
    /// bus cycles (a piece of work of its own, so a cycle waits for one module's reads at most). A module that does not
    /// answer (noise, a reset, a module gone silent) is tried again on a later turn, up to <see cref="ReadTries"/>
    /// times, and the event log says so; after that its parameters stay unknown and the session goes on.
    /// </summary>
    public void ReadNextWaiting()
    {
        if (_reading is { IsCompleted: false } || !_waiting.TryDequeue(out var c))
        {
            return;
        }

        _reading = ReadAsync(c).ContinueWith(t => Done(c, t.Result), TaskScheduler.Default);
    }

    /// <summary>
    /// Reads a module's parameters between bus cycles, one parameter of one motor per piece of work: a gap between two
    /// cycles carries one transaction (and its retries) at most, however many reads are asked for at once, so the
    /// cycle and a loop sharing its thread (the virtual robot's schedule) keep their time. The first failure ends it.
    /// </summary>
    public async Task<CommandResult> ReadAsync(RobotController c)
    {
        foreach (var m in c.Motors)
        {
            foreach (var p in MotorParameter.All)
            {
                var read = await commands.Submit(() =>
                {
                    _values[(c.Id, m.Config.Channel, p.Key)] = p.FromCounts(m.Config, bus.ReadParameter(c.Id, p.Field.Name, m.Config.Channel));
                    return CommandResult.Ok(string.Empty);
                }).ConfigureAwait(false);
                if (!read.Succeeded)
                {
                    return read;
                }
            }
        }

        return CommandResult.Ok($"module {c.Id}: parameters read");
    }

    /// <summary>Keeps a value written and read back (the bus's owner).</summary>
    public void Keep(int module, int channel, string key, double value) => _values[(module, channel, key)] = value;

    /// <summary>The value last read or written back, NaN when unknown.</summary>
    public double Value(int module, int channel, string key) => _values.TryGetValue((module, channel, key), out var v) ? v : double.NaN;

    private CommandResult Done(RobotController c, CommandResult result)
    {
        if (result.Succeeded)
        {
            return result;
        }

        var tries = _tries[c.Id] = _tries.GetValueOrDefault(c.Id) + 1;
        if (tries < ReadTries)
        {
            _waiting.Enqueue(c);
            events.Add("bus", $"{result.Message}; reading module {c.Id}'s parameters again later (try {tries} of {ReadTries})");
        }
        else
        {
            events.Add("bus", $"{result.Message}; module {c.Id}'s parameters stay unknown after {tries} tries (reload them from the bus page)");
        }

        return result;
    }
}
