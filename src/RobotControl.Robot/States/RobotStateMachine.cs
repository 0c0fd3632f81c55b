namespace RobotControl.Robot.States;

/// <summary>
/// The robot's states and the moves between them, declared once each (<see cref="Declare"/>: the state, what runs
/// when it is entered, and which states may follow), as an arm's states are declared in one place in
/// sawIntuitiveResearchKit. A move records its time, origin, target and reason (<see cref="History"/>); a move the
/// declaration does not allow is refused with an <see cref="InvalidOperationException"/> naming the action, the
/// state and what the action needs, and changes nothing. Preconditions of actions are checked here
/// (<see cref="Require"/>), not described in prose. Thread-safe (moves are rare: setup, faults).
/// </summary>
public sealed class RobotStateMachine
{
    private readonly Lock _gate = new();
    private readonly TimeProvider _time;
    private readonly long _origin;
    private readonly Dictionary<RobotState, Declaration> _declared = [];
    private readonly List<RobotTransition> _history = [];
    private volatile RobotState _current;

    /// <summary>A machine in <paramref name="initial"/>, timing its moves on <paramref name="time"/>.</summary>
    public RobotStateMachine(TimeProvider time, RobotState initial = RobotState.Disabled)
    {
        ArgumentNullException.ThrowIfNull(time);
        _time = time;
        _origin = time.GetTimestamp();
        _current = initial;
    }

    /// <summary>The state now.</summary>
    public RobotState Current => _current;

    /// <summary>Every move so far, oldest first (a copy).</summary>
    public IReadOnlyList<RobotTransition> History
    {
        get
        {
            lock (_gate)
            {
                return [.. _history];
            }
        }
    }

    /// <summary>Declares <paramref name="state"/>: the states that may follow it, and what runs when it is entered.</summary>
    /// <exception cref="InvalidOperationException">The state is declared already.</exception>
    public void Declare(RobotState state, Action? enter, params RobotState[] next)
    {
        ArgumentNullException.ThrowIfNull(next);
        if (!_declared.TryAdd(state, new Declaration(enter, [.. next])))
        {
            throw new InvalidOperationException($"robot state {state} is declared twice");
        }
    }

    /// <summary>True when the declaration lets the robot move from the current state to <paramref name="to"/>.</summary>
    public bool CanMoveTo(RobotState to) => Allowed(_current, to);

    /// <summary>
    /// Moves to <paramref name="to"/> for <paramref name="reason"/>, runs its enter action and records the move. Staying in
    /// the current state is no move (nothing runs or is recorded).
    /// </summary>
    /// <exception cref="InvalidOperationException">The declaration does not allow the move (nothing changes).</exception>
    public void MoveTo(RobotState to, string reason)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(reason);
        Action? enter;
        lock (_gate)
        {
            var from = _current;
            if (from == to)
            {
                return;
            }

            if (!Allowed(from, to))
            {
                throw new InvalidOperationException($"the robot cannot go from {from} to {to} ({reason}); from {from} it may go to {Successors(from)}");
            }

            _history.Add(new RobotTransition(_time.GetElapsedTime(_origin), from, to, reason));
            _current = to;
            enter = _declared[to].Enter;
        }

        enter?.Invoke();
    }

    /// <summary>Refuses <paramref name="action"/> unless the robot is in one of <paramref name="states"/>.</summary>
    /// <exception cref="InvalidOperationException">It is not; the message names the action, the state and <paramref name="hint"/>.</exception>
    public void Require(string action, string hint, params RobotState[] states)
    {
        ArgumentNullException.ThrowIfNull(states);
        var now = _current;
        if (Array.IndexOf(states, now) < 0)
        {
            throw new InvalidOperationException($"{action} needs the robot {string.Join(" or ", states)}, it is {now}: {hint}");
        }
    }

    private bool Allowed(RobotState from, RobotState to) =>
        from == to || (_declared.TryGetValue(from, out var d) && Array.IndexOf(d.Next, to) >= 0);

    private string Successors(RobotState from) =>
        _declared.TryGetValue(from, out var d) && d.Next.Length > 0 ? string.Join(", ", d.Next) : "nowhere";

    private sealed record Declaration(Action? Enter, RobotState[] Next);
}
