using System.Runtime.CompilerServices;

namespace RobotControl.Robot.Control.States;

/// <summary>
/// States and the moves between them, each state declared once (<see cref="Declare"/>: the state, what runs when it
/// is entered, which states may follow), as an arm's states are declared in one place in sawIntuitiveResearchKit's
/// <c>Init()</c>. Every move is recorded with its time, source and reason (<see cref="History"/>). A move the
/// declarations do not allow is refused with one line naming the states, the move and what may follow, and changes
/// nothing; staying in the current state is no move. Preconditions of actions are checked here (<see cref="Require"/>).
/// <para>
/// Threads: states are declared while the owner is built, before the first move; moves come from one thread (the
/// bus thread); <see cref="Current"/>, <see cref="CanMoveTo"/>, <see cref="Require"/> and <see cref="History"/> may be
/// read from any thread (<see cref="Current"/> lock-free and allocation-free).
/// </para>
/// </summary>
/// <typeparam name="TState">The states.</typeparam>
public sealed class StateMachine<TState>
    where TState : struct, Enum
{
    private readonly Lock _gate = new();
    private readonly TimeProvider _time;
    private readonly Func<TState, string> _nameOf;
    private readonly Dictionary<TState, Declaration> _declared = [];
    private readonly List<StateTransition<TState>> _history = [];
    private int _moves;
    private volatile StrongBox<TState> _current; // replaced whole on a move: a reader never sees a torn state

    /// <summary>A machine in <paramref name="initial"/>, timing its moves on <paramref name="time"/>.</summary>
    /// <param name="subject">What is in these states, as messages name it ("the robot", "the run level").</param>
    /// <param name="time">The clock of <see cref="StateTransition{TState}.Timestamp"/>.</param>
    /// <param name="initial">The state before any move.</param>
    /// <param name="nameOf">How messages name a state (default: its enum name).</param>
    public StateMachine(string subject, TimeProvider time, TState initial, Func<TState, string>? nameOf = null)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(subject);
        ArgumentNullException.ThrowIfNull(time);
        Subject = subject;
        _time = time;
        _nameOf = nameOf ?? (s => s.ToString());
        _current = new StrongBox<TState>(initial);
    }

    /// <summary>What is in these states, as messages name it.</summary>
    public string Subject { get; }

    /// <summary>The state now.</summary>
    public TState Current => _current.Value;

    /// <summary>Moves so far, read without the lock: a reader that polls copies <see cref="History"/> only when it grew.</summary>
    public int MoveCount => Volatile.Read(ref _moves);

    /// <summary>Every move so far, oldest first (a copy).</summary>
    public IReadOnlyList<StateTransition<TState>> History
    {
        get
        {
            lock (_gate)
            {
                return [.. _history];
            }
        }
    }

    /// <summary>Declares <paramref name="state"/>: what runs when it is entered, and the states that may follow it.</summary>
    /// <exception cref="InvalidOperationException">The state is declared already, or the machine has moved.</exception>
    public void Declare(TState state, Action? enter, params TState[] next)
    {
        ArgumentNullException.ThrowIfNull(next);
        lock (_gate)
        {
            if (_history.Count > 0)
            {
                throw new InvalidOperationException($"{Subject}: state {_nameOf(state)} is declared after the first move; declare every state first");
            }

            if (!_declared.TryAdd(state, new Declaration(enter, [.. next])))
            {
                throw new InvalidOperationException($"{Subject}: state {_nameOf(state)} is declared twice");
            }
        }
    }

    /// <summary>True when the declarations let the machine move from the current state to <paramref name="to"/> (or stay).</summary>
    public bool CanMoveTo(TState to) => Allowed(Current, to);

    /// <summary>
    /// Moves to <paramref name="to"/>, records the move, then runs the enter action of <paramref name="to"/>. Staying in
    /// the current state is no move: nothing runs or is recorded.
    /// </summary>
    /// <returns>True when the machine moved, false when it stayed.</returns>
    /// <exception cref="InvalidOperationException">The declarations do not allow the move (nothing changes).</exception>
    public bool MoveTo(TState to, string source, string reason)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(source);
        ArgumentException.ThrowIfNullOrWhiteSpace(reason);
        Action? enter;
        lock (_gate)
        {
            var from = Current;
            if (EqualityComparer<TState>.Default.Equals(from, to))
            {
                return false;
            }

            if (!Allowed(from, to) || !_declared.TryGetValue(to, out var target))
            {
                throw new InvalidOperationException($"{Subject} cannot go from {_nameOf(from)} to {_nameOf(to)} ({source}: {reason}); from {_nameOf(from)} it may go to {Successors(from)}");
            }

            _history.Add(new StateTransition<TState>(_time.GetTimestamp(), from, to, source, reason));
            Volatile.Write(ref _moves, _history.Count);
            _current = new StrongBox<TState>(to);
            enter = target.Enter;
        }

        enter?.Invoke();
        return true;
    }

    /// <summary>Refuses <paramref name="action"/> unless the machine is in one of <paramref name="states"/>.</summary>
    /// <exception cref="InvalidOperationException">It is not; the message names the action, the states it needs, the state now and <paramref name="hint"/>.</exception>
    public void Require(string action, string hint, params TState[] states)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(action);
        ArgumentNullException.ThrowIfNull(states);
        var now = Current;
        if (Array.IndexOf(states, now) < 0)
        {
            throw new InvalidOperationException($"{action} needs {Subject} {string.Join(" or ", states.Select(_nameOf))}, it is {_nameOf(now)}: {hint}");
        }
    }

    private bool Allowed(TState from, TState to) =>
        EqualityComparer<TState>.Default.Equals(from, to) || (_declared.TryGetValue(from, out var d) && Array.IndexOf(d.Next, to) >= 0);

    private string Successors(TState from) =>
        _declared.TryGetValue(from, out var d) && d.Next.Length > 0 ? string.Join(", ", d.Next.Select(_nameOf)) : "nowhere";

    private sealed record Declaration(Action? Enter, TState[] Next);
}
