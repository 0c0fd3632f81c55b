using RobotControl.Robot.Control.States;

namespace RobotControl.Robot.Control.Tests.States;

/// <summary>The one state machine of the robot's life and the run levels: declarations, moves, refusals, history, threads.</summary>
public sealed class StateMachineTests
{
    private enum Door
    {
        Closed,
        Opening,
        Open,
        Locked,
        Broken,
    }

    /// <summary>Closed -> Opening -> Open -> Closed, Closed <-> Locked; Broken is never declared.</summary>
    private static StateMachine<Door> Machine(TimeProvider clock, List<string>? entered = null)
    {
        var m = new StateMachine<Door>("the door", clock, Door.Closed, d => d.ToString().ToUpperInvariant());
        m.Declare(Door.Closed, () => entered?.Add("closed"), Door.Opening, Door.Locked);
        m.Declare(Door.Opening, () => entered?.Add("opening"), Door.Open, Door.Closed, Door.Broken);
        m.Declare(Door.Open, () => entered?.Add("open"), Door.Closed);
        m.Declare(Door.Locked, () => entered?.Add("locked"), Door.Closed);
        return m;
    }

    [Fact]
    public void The_move_count_follows_the_history_and_a_stay_or_a_refused_move_does_not_count()
    {
        var m = Machine(new SteppedClock());
        Assert.Equal(0, m.MoveCount);
        m.MoveTo(Door.Opening, "operator", "open button");
        m.MoveTo(Door.Opening, "operator", "pressed again");
        Assert.Throws<InvalidOperationException>(() => m.MoveTo(Door.Locked, "operator", "lock while opening"));
        m.MoveTo(Door.Open, "motor", "fully open");

        Assert.Equal(2, m.MoveCount);
        Assert.Equal(m.History.Count, m.MoveCount);
    }

    [Fact]
    public void Every_move_runs_the_enter_action_once_and_is_recorded_with_time_source_and_reason()
    {
        var clock = new SteppedClock();
        var entered = new List<string>();
        var m = Machine(clock, entered);
        Assert.True(m.MoveTo(Door.Opening, "operator", "open button"));
        clock.Ticks = 250;
        Assert.True(m.MoveTo(Door.Open, "motor", "fully open"));
        clock.Ticks = 400;
        Assert.True(m.MoveTo(Door.Closed, "timer", "closes after 150 ms"));

        Assert.Equal(Door.Closed, m.Current);
        Assert.Equal(["opening", "open", "closed"], entered);
        Assert.Equal(
            [
                new StateTransition<Door>(0, Door.Closed, Door.Opening, "operator", "open button"),
                new StateTransition<Door>(250, Door.Opening, Door.Open, "motor", "fully open"),
                new StateTransition<Door>(400, Door.Open, Door.Closed, "timer", "closes after 150 ms"),
            ],
            m.History);
    }

    [Fact]
    public void Staying_in_the_current_state_is_no_move_nothing_runs_or_is_recorded()
    {
        var entered = new List<string>();
        var m = Machine(new SteppedClock(), entered);
        Assert.True(m.CanMoveTo(Door.Closed));
        Assert.False(m.MoveTo(Door.Closed, "operator", "close button"));
        m.MoveTo(Door.Locked, "operator", "lock");
        Assert.False(m.MoveTo(Door.Locked, "operator", "lock again"));

        Assert.Equal(["locked"], entered);
        Assert.Equal((Door.Closed, Door.Locked, "lock"), (m.History.Single().From, m.History.Single().To, m.History.Single().Reason));
    }

    [Fact]
    public void A_refused_move_changes_nothing_and_says_in_one_line_what_may_follow()
    {
        var entered = new List<string>();
        var m = Machine(new SteppedClock(), entered);
        m.MoveTo(Door.Locked, "operator", "lock");

        var error = Assert.Throws<InvalidOperationException>(() => m.MoveTo(Door.Opening, "operator", "open button"));
        Assert.Equal("the door cannot go from LOCKED to OPENING (operator: open button); from LOCKED it may go to CLOSED", error.Message);
        Assert.False(m.CanMoveTo(Door.Opening));
        Assert.Equal(Door.Locked, m.Current);
        Assert.Equal(["locked"], entered);
        Assert.Single(m.History);

        m.MoveTo(Door.Closed, "operator", "unlock");
        m.MoveTo(Door.Opening, "operator", "open button");
        Assert.True(m.CanMoveTo(Door.Broken)); // listed as a follower, but never declared: refused all the same
        Assert.Throws<InvalidOperationException>(() => m.MoveTo(Door.Broken, "motor", "stalled"));
        Assert.Equal(Door.Opening, m.Current);
        Assert.Equal(["locked", "closed", "opening"], entered);
        Assert.Equal(3, m.History.Count);
    }

    [Fact]
    public void A_state_with_no_followers_may_go_nowhere()
    {
        var m = new StateMachine<Door>("the door", new SteppedClock(), Door.Closed);
        m.Declare(Door.Closed, null);
        m.Declare(Door.Open, null);
        var error = Assert.Throws<InvalidOperationException>(() => m.MoveTo(Door.Open, "operator", "open"));
        Assert.Equal("the door cannot go from Closed to Open (operator: open); from Closed it may go to nowhere", error.Message);
    }

    [Fact]
    public void A_state_is_declared_once_and_every_state_before_the_first_move()
    {
        var m = Machine(new SteppedClock());
        var twice = Assert.Throws<InvalidOperationException>(() => m.Declare(Door.Open, null, Door.Closed));
        Assert.Equal("the door: state OPEN is declared twice", twice.Message);
        m.MoveTo(Door.Opening, "operator", "open button");
        var late = Assert.Throws<InvalidOperationException>(() => m.Declare(Door.Broken, null));
        Assert.Contains("declared after the first move", late.Message, StringComparison.Ordinal);
        Assert.Throws<InvalidOperationException>(() => m.MoveTo(Door.Broken, "motor", "stalled"));
    }

    [Fact]
    public void An_action_is_refused_outside_the_states_it_needs_with_the_action_the_states_and_a_hint()
    {
        var m = new StateMachine<Door>("the robot", new SteppedClock(), Door.Closed);
        m.Declare(Door.Closed, null, Door.Open);
        m.Declare(Door.Open, null, Door.Closed);
        m.Require("homing", "discover first", Door.Closed, Door.Locked); // in a state it needs: nothing happens

        m.MoveTo(Door.Open, "operator", "open");
        var error = Assert.Throws<InvalidOperationException>(() => m.Require("homing", "discover first", Door.Closed, Door.Locked));
        Assert.Equal("homing needs the robot Closed or Locked, it is Open: discover first", error.Message);
        Assert.Equal(Door.Open, m.Current);
    }

    [Fact]
    public void A_move_needs_a_source_and_a_reason_and_without_them_changes_nothing()
    {
        var m = Machine(new SteppedClock());
        Assert.Throws<ArgumentException>(() => m.MoveTo(Door.Opening, " ", "open button"));
        Assert.Throws<ArgumentException>(() => m.MoveTo(Door.Opening, "operator", ""));
        Assert.Equal(Door.Closed, m.Current);
        Assert.Empty(m.History);
        Assert.Throws<ArgumentException>(() => new StateMachine<Door>(" ", new SteppedClock(), Door.Closed));
    }

    [Fact]
    public void History_is_a_copy_that_later_moves_do_not_change()
    {
        var m = Machine(new SteppedClock());
        var before = m.History;
        m.MoveTo(Door.Locked, "operator", "lock");
        Assert.Empty(before);
        Assert.Single(m.History);
    }

    [Fact]
    public void Readers_on_other_threads_see_whole_states_and_consistent_histories_while_one_thread_moves()
    {
        var m = Machine(new SteppedClock());
        const int Moves = 20_000;
        using var done = new ManualResetEventSlim();
        var problems = new List<string>();
        var reader = new Thread(() =>
        {
            while (!done.IsSet)
            {
                var now = m.Current;
                if (now is not (Door.Closed or Door.Locked))
                {
                    problems.Add($"state {now}");
                }

                var history = m.History;
                for (var i = 1; i < history.Count; i++)
                {
                    if (history[i].From != history[i - 1].To)
                    {
                        problems.Add($"move {i} starts at {history[i].From}, the one before ended at {history[i - 1].To}");
                    }
                }
            }
        });
        reader.Start();
        for (var i = 0; i < Moves; i++)
        {
            m.MoveTo(i % 2 == 0 ? Door.Locked : Door.Closed, "writer", "toggle");
        }

        done.Set();
        reader.Join();
        Assert.Empty(problems);
        Assert.Equal(Moves, m.History.Count);
        Assert.Equal(Door.Closed, m.Current);
    }

    /// <summary>A clock that stands still until a test sets it (one tick per timestamp unit).</summary>
    private sealed class SteppedClock : TimeProvider
    {
        public long Ticks { get; set; }

        public override long TimestampFrequency => 1000;

        public override long GetTimestamp() => Ticks;
    }
}
