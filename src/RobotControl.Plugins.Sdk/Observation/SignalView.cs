namespace RobotControl.Plugins.Sdk.Observation;

/// <summary>Read-only view of a set of named signals whose values the host updates in place every tick.</summary>
public sealed class SignalView
{
    private readonly double[] _values;
    private readonly int _offset;

    /// <summary>Creates a view of <paramref name="names"/>.Count values of <paramref name="values"/> starting at <paramref name="offset"/>.</summary>
    public SignalView(IReadOnlyList<string> names, double[] values, int offset = 0)
    {
        ArgumentNullException.ThrowIfNull(names);
        ArgumentNullException.ThrowIfNull(values);
        ArgumentOutOfRangeException.ThrowIfNegative(offset);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(offset + names.Count, values.Length);
        Names = names;
        _values = values;
        _offset = offset;
    }

    /// <summary>Signal names (<c>instance.port</c>), in value order.</summary>
    public IReadOnlyList<string> Names { get; }

    /// <summary>The current values (allocation-free).</summary>
    public ReadOnlySpan<double> Values => _values.AsSpan(_offset, Names.Count);
}
