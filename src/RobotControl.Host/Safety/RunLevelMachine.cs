namespace RobotControl.Host.Safety;

/// <summary>
/// The run levels and the moves between them, declared once (<see cref="Declared"/>); every move is recorded with its
/// time, source and reason. A move the table does not allow is refused with one line naming the levels and what may
/// follow, and changes nothing. There is no automatic recovery: the only way out of <see cref="RunLevel.EStop"/> is
/// an operator reset to <see cref="RunLevel.Init"/>. Thread-safe (moves are rare).
/// </summary>
public sealed class RunLevelMachine
{
    /// <summary>Which levels may follow each level.</summary>
    public static readonly IReadOnlyDictionary<RunLevel, RunLevel[]> Declared = new Dictionary<RunLevel, RunLevel[]>
    {
        [RunLevel.EStop] = [RunLevel.Init],
        [RunLevel.Init] = [RunLevel.Homing, RunLevel.EStop],
        [RunLevel.Homing] = [RunLevel.PedalUp, RunLevel.Init, RunLevel.EStop],
        [RunLevel.PedalUp] = [RunLevel.PedalDown, RunLevel.Init, RunLevel.EStop],
        [RunLevel.PedalDown] = [RunLevel.PedalUp, RunLevel.EStop],
    };

    private readonly Lock _gate = new();
    private readonly TimeProvider _time;
    private readonly List<RunLevelTransition> _history = new(64);
    private volatile RunLevel _current = RunLevel.Init;

    /// <summary>A machine at <see cref="RunLevel.Init"/>, timing its moves on <paramref name="time"/>.</summary>
    public RunLevelMachine(TimeProvider time)
    {
        ArgumentNullException.ThrowIfNull(time);
        _time = time;
    }

    /// <summary>The level now.</summary>
    public RunLevel Current => _current;

    /// <summary>Every move so far, oldest first (a copy).</summary>
    public IReadOnlyList<RunLevelTransition> History
    {
        get
        {
            lock (_gate)
            {
                return [.. _history];
            }
        }
    }

    /// <summary>True when the table lets the level go from the current one to <paramref name="to"/>.</summary>
    public bool CanMoveTo(RunLevel to) => Allowed(_current, to);

    /// <summary>Moves to <paramref name="to"/> and records it; staying is no move. Returns the level left.</summary>
    /// <exception cref="InvalidOperationException">The table does not allow the move (nothing changes).</exception>
    public RunLevel MoveTo(RunLevel to, string source, string reason)
    {
        lock (_gate)
        {
            var from = _current;
            if (from == to)
            {
                return from;
            }

            if (!Allowed(from, to))
            {
                throw new InvalidOperationException($"run level {from.Name()} cannot go to {to.Name()} ({source}: {reason}); from {from.Name()} it may go to {string.Join(", ", Declared[from].Select(l => l.Name()))}");
            }

            _history.Add(new RunLevelTransition(_time.GetTimestamp(), from, to, source, reason));
            _current = to;
            return from;
        }
    }

    private static bool Allowed(RunLevel from, RunLevel to) => from == to || Array.IndexOf(Declared[from], to) >= 0;
}
