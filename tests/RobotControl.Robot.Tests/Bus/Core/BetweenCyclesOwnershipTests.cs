using RobotControl.Robot.Bus;

namespace RobotControl.Robot.Tests.Bus.Core;

/// <summary>
/// The one slot for work between cycles: who owns the bus, work run at once while nobody does, queued while another
/// thread does, and failed when the owner stops before it ran.
/// </summary>
public sealed class BetweenCyclesOwnershipTests
{
    [Fact]
    public async Task While_nobody_owns_the_bus_work_runs_at_once_on_the_caller()
    {
        using var rig = new TappedLb(start: false);
        var slot = rig.Robot.Slot;
        Assert.False(slot.IsOwner);
        Assert.True(slot.OnBusThread);

        var posted = slot.Post("now", () => Environment.CurrentManagedThreadId);
        Assert.True(posted.IsCompletedSuccessfully);
        Assert.Equal(Environment.CurrentManagedThreadId, await posted);
        var ran = 0;
        slot.Run("an action", () => ran++);
        Assert.Equal(1, ran);
        Assert.Equal(0, slot.Pending);
    }

    [Fact]
    public void Work_needs_a_name_and_a_body()
    {
        using var rig = new TappedLb(start: false);
        var slot = rig.Robot.Slot;
        Assert.Throws<ArgumentNullException>(() => slot.Run("nothing", null!));
        Assert.Throws<ArgumentException>(() => { _ = slot.Post(" ", () => 1); });
        Assert.Throws<ArgumentNullException>(() => { _ = slot.Post<int>("nothing", null!); });
    }

    [Fact]
    public async Task The_owner_runs_its_own_calls_at_once_and_other_threads_queue_theirs_until_it_lets_go()
    {
        using var rig = new TappedLb(start: false);
        var robot = rig.Robot;
        var slot = robot.Slot;
        Task<int> stranded;
        using (robot.OwnBus())
        {
            Assert.True(slot.IsOwner);
            Assert.True(slot.OnBusThread);
            Assert.Equal((false, false), OnOtherThread(() => (slot.IsOwner, slot.OnBusThread)));
            Assert.Equal(Environment.CurrentManagedThreadId, slot.Run("mine", () => Environment.CurrentManagedThreadId));

            // Nested ownership by the owner (a schedule calling RunFor): the cycles run the queued work, and letting go
            // of the inner ownership keeps the outer. With no module to talk to, the time passes on the link.
            var queued = OnOtherThread(() => slot.Post("queued", () => 7));
            Assert.Equal(1, slot.Pending);
            var before = rig.Clock.Elapsed;
            robot.RunFor(TimeSpan.FromMilliseconds(5));
            Assert.InRange(rig.Clock.Elapsed - before, TimeSpan.FromMilliseconds(5), TimeSpan.FromMilliseconds(5.01));
            Assert.True(slot.IsOwner);
            Assert.Equal(0, robot.Cycles); // nothing to cycle with
            Assert.True(queued.IsCompletedSuccessfully);
            Assert.Equal(7, await queued); // completed: no thread switch
            Assert.Equal(0, slot.Pending);
            Assert.Empty(rig.Tap.Sent);

            stranded = OnOtherThread(() => slot.Post("stranded", () => 8));
            var ranBefore = slot.Ran;
            robot.EmergencyHold("stop", torqueOff: false); // no piece starts while a stop is on its way
            robot.RunBetweenCycles();
            Assert.Equal((1, ranBefore), (slot.Pending, slot.Ran));
            robot.Write();
            Assert.False(stranded.IsCompleted);

            // Another thread cannot run cycles meanwhile.
            var refused = OnOtherThread(() => Record.Exception(() => robot.RunFor(TimeSpan.FromMilliseconds(1))));
            Assert.Equal($"the bus is owned by the thread \"{Thread.CurrentThread.Name}\"; run cycles on one thread at a time", Assert.IsType<InvalidOperationException>(refused).Message);
            Assert.Equal(1, slot.Pending);
        }

        // Letting go of the bus fails what is still queued (nothing was sent for it); then work runs at once again.
        Assert.True(stranded.IsFaulted);
        var failure = await Assert.ThrowsAsync<InvalidOperationException>(() => stranded);
        Assert.Equal("the bus cycles stopped before this ran; nothing was sent", failure.Message);
        Assert.False(slot.IsOwner);
        Assert.True(slot.OnBusThread);
        Assert.Equal(0, slot.Pending);
        var after = OnOtherThread(() => slot.Post("after", () => 9));
        Assert.True(after.IsCompletedSuccessfully);
    }

    /// <summary>Runs <paramref name="call"/> on a thread of its own and returns what it returned.</summary>
    private static T OnOtherThread<T>(Func<T> call)
    {
        T result = default!;
        var thread = new Thread(() => result = call());
        thread.Start();
        thread.Join();
        return result;
    }
}
