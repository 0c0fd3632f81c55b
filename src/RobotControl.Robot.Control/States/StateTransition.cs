namespace RobotControl.Robot.Control.States;

/// <summary>One move of a <see cref="StateMachine{TState}"/>, as recorded.</summary>
/// <typeparam name="TState">The machine's states.</typeparam>
/// <param name="Timestamp">When, on the machine's clock (<see cref="TimeProvider.GetTimestamp"/>).</param>
/// <param name="From">The state left.</param>
/// <param name="To">The state entered.</param>
/// <param name="Source">Who asked (an operator, the pedal, a part of the robot core, the check that tripped).</param>
/// <param name="Reason">Why.</param>
public sealed record StateTransition<TState>(long Timestamp, TState From, TState To, string Source, string Reason)
    where TState : struct, Enum;
