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
}
