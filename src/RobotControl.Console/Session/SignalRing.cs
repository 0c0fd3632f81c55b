namespace RobotControl.WebConsole.Session;

/// <summary>
/// A fixed ring of signal rows (time + one value per signal) written by one thread (the loop, after each tick) and
/// read by any number of others without locks. <see cref="Append"/> allocates nothing: it copies into preallocated
/// storage and then publishes the row count. A reader copies the rows it wants and drops any the writer may have
/// overwritten meanwhile (it checks the count again after copying), so it never returns a torn row.
/// </summary>
public sealed class SignalRing
{
    private readonly double[] _data;
    private readonly int _stride;
    private readonly Dictionary<string, int> _index;
    private long _written;

    /// <summary>Creates a ring of <paramref name="capacity"/> rows of <paramref name="names"/>.</summary>
    public SignalRing(IReadOnlyList<string> names, IReadOnlyList<string> units, int capacity)
    {
        ArgumentNullException.ThrowIfNull(names);
        ArgumentNullException.ThrowIfNull(units);
        ArgumentOutOfRangeException.ThrowIfLessThan(capacity, 2);
        if (units.Count != names.Count)
        {
            throw new ArgumentException("one unit per signal", nameof(units));
        }

        Names = names;
        Units = units;
        Capacity = capacity;
        _stride = names.Count + 1;
        _data = new double[capacity * _stride];
        _index = new Dictionary<string, int>(names.Count, StringComparer.Ordinal);
        for (var i = 0; i < names.Count; i++)
        {
            _index[names[i]] = i;
        }
    }

    /// <summary>Signal names, in column order.</summary>
    public IReadOnlyList<string> Names { get; }

    /// <summary>Units, one per signal.</summary>
    public IReadOnlyList<string> Units { get; }

    /// <summary>Rows kept.</summary>
    public int Capacity { get; }

    /// <summary>Rows written so far (the next row's sequence number).</summary>
    public long Written => Volatile.Read(ref _written);

    /// <summary>The column of <paramref name="name"/>, or -1.</summary>
    public int IndexOf(string name) => _index.TryGetValue(name, out var i) ? i : -1;

    /// <summary>Appends one row (single writer). <paramref name="values"/> holds one value per signal.</summary>
    public void Append(double timeSeconds, ReadOnlySpan<double> values)
    {
        var row = _written;
        var at = (int)(row % Capacity) * _stride;
        _data[at] = timeSeconds;
        values[..Math.Min(values.Length, _stride - 1)].CopyTo(_data.AsSpan(at + 1));
        Volatile.Write(ref _written, row + 1);
    }

    /// <summary>
    /// Copies rows from sequence <paramref name="from"/> on (older rows than the ring holds are skipped), at most
    /// <paramref name="maxRows"/> of them evenly spaced, taking the time and the <paramref name="columns"/> of each.
    /// </summary>
    /// <returns>The times, one value list per column, and the sequence to continue from.</returns>
    public RingSlice Read(long from, IReadOnlyList<int> columns, int maxRows)
    {
        ArgumentNullException.ThrowIfNull(columns);
        ArgumentOutOfRangeException.ThrowIfLessThan(maxRows, 1);
        var end = Written;

        // Keep a margin of rows the writer may be filling while we copy.
        var oldest = Math.Max(0, end - Capacity + 64);
        var start = Math.Max(from, oldest);
        var count = Math.Max(0, end - start);
        var step = Math.Max(1, (count + maxRows - 1) / maxRows);
        var times = new List<double>();
        var values = columns.Select(_ => new List<double>()).ToArray();
        for (var row = start; row < end; row += step)
        {
            var at = (int)(row % Capacity) * _stride;
            times.Add(_data[at]);
            for (var c = 0; c < columns.Count; c++)
            {
                values[c].Add(_data[at + 1 + columns[c]]);
            }
        }

        // Rows the writer may have overwritten while we copied are dropped from the front.
        var lapped = Written - Capacity;
        var drop = 0;
        for (var row = start; row < lapped && drop < times.Count; row += step)
        {
            drop++;
        }

        if (drop > 0)
        {
            times.RemoveRange(0, drop);
            foreach (var v in values)
            {
                v.RemoveRange(0, drop);
            }
        }

        return new RingSlice(times, values, end);
    }
}

/// <summary>Rows read from a <see cref="SignalRing"/>.</summary>
/// <param name="Times">Row times, seconds.</param>
/// <param name="Values">One list per requested column.</param>
/// <param name="Next">The sequence to read from next time.</param>
public sealed record RingSlice(IReadOnlyList<double> Times, IReadOnlyList<IReadOnlyList<double>> Values, long Next);
