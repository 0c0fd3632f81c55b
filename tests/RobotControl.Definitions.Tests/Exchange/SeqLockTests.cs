using RobotControl.Definitions.Exchange;

namespace RobotControl.Definitions.Tests.Exchange;

public sealed class SeqLockTests
{
    [Fact]
    public void A_reader_gets_the_last_complete_write_and_its_number()
    {
        var values = new SeqLock<double>(3);
        Span<double> read = stackalloc double[3];
        Assert.Equal(0, values.Read(read));
        Assert.Equal([0.0, 0.0, 0.0], read.ToArray());

        values.Write([1.0, 2.0, 3.0, 99.0]); // only the first Length values count
        values.Write([4.0, 5.0, 6.0]);
        Assert.Equal(2, values.Read(read));
        Assert.Equal(2, values.Version);
        Assert.Equal([4.0, 5.0, 6.0], read.ToArray());
        Assert.Throws<ArgumentOutOfRangeException>(() => new SeqLock<int>(0));
    }

    [Fact]
    public void Concurrent_readers_never_see_a_mix_of_two_writes()
    {
        const int Length = 64;
        var values = new SeqLock<long>(Length);
        using var stop = new CancellationTokenSource();
        var writer = new Thread(() =>
        {
            var v = new long[Length];
            for (long n = 1; !stop.IsCancellationRequested; n++)
            {
                Array.Fill(v, n);
                values.Write(v);
            }
        });
        writer.Start();

        var read = new long[Length];
        var torn = 0;
        var deadline = DateTime.UtcNow + TimeSpan.FromMilliseconds(300);
        while (DateTime.UtcNow < deadline)
        {
            values.Read(read);
            torn += read.Any(x => x != read[0]) ? 1 : 0;
        }

        stop.Cancel();
        writer.Join();
        Assert.Equal(0, torn);
        Assert.True(values.Version > 0);
    }

    [Fact]
    public void A_reader_never_waits_for_a_write_left_half_done()
    {
        // A writer preempted in the middle of a write (on a loaded machine) must not hold the control loop: the reader
        // gets the last complete write at once. Before the two slots, this Read spun until the write ended.
        var values = new SeqLock<double>(2);
        values.Write([1.0, 2.0]);
        var open = values.BeginWrite();
        open[0] = 7; // half of the next write

        var read = new double[2];
        var version = -1;
        var reader = new Thread(() => version = values.Read(read)) { IsBackground = true };
        reader.Start();

        // A hang guard, not a timing: with a reader that waits for the writer, the write never ends and this fails.
        Assert.True(reader.Join(TimeSpan.FromSeconds(30)), "the reader waited for the open write");
        Assert.Equal(1, version);
        Assert.Equal([1.0, 2.0], read);

        open[1] = 8;
        values.EndWrite();
        Assert.Equal(2, values.Read(read));
        Assert.Equal([7.0, 8.0], read);
    }

    [Fact]
    public void Writes_alternate_slots_and_a_read_is_always_the_latest_complete_one()
    {
        var values = new SeqLock<int>(3);
        var read = new int[3];
        for (var n = 1; n <= 5; n++)
        {
            values.Write([n, n * 10, n * 100]);
            Assert.Equal(n, values.Read(read));
            Assert.Equal([n, n * 10, n * 100], read);
        }
    }

    [Fact]
    public void The_write_count_may_wrap_past_int_max_value_without_holding_a_reader()
    {
        // At a few thousand writes a second the count wraps after days: a reader must still return at once, and the
        // latest complete write, on both sides of the wrap (with a write left open across it, too).
        var values = new SeqLock<int>(1, int.MaxValue - 5);
        for (var n = 1; n <= 6; n++)
        {
            values.Write([n]);
            Assert.Equal(n, ReadOnAnotherThread(values, $"after write {n}"));
            var open = values.BeginWrite();
            open[0] = -n; // left open while a reader reads
            Assert.Equal(n, ReadOnAnotherThread(values, $"with write {n + 1} open"));
            values.EndWrite();
            Assert.Equal(-n, ReadOnAnotherThread(values, $"after write {n + 1}"));
        }
    }

    /// <summary>Reads on a background thread, so that a reader that never returns fails the test instead of hanging it.</summary>
    private static int ReadOnAnotherThread(SeqLock<int> values, string when)
    {
        var read = new int[1];
        var reader = new Thread(() => values.Read(read)) { IsBackground = true };
        reader.Start();
        Assert.True(reader.Join(TimeSpan.FromSeconds(30)), $"the reader did not return {when}"); // a hang guard, not a timing
        return read[0];
    }
}
