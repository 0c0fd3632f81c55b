using System.Globalization;

namespace RobotControl.Plugins.Standard.Pedals;

/// <summary>
/// A simulated pedal box: a script of <c>time_s:mask</c> steps (e.g. <c>2.5:1,3.1:0,6:2</c>; mask bit i = pedal
/// i+1), evaluated at loop time: deterministic.
/// </summary>
public sealed class ScriptedPedalSource : IPedalSource
{
    private readonly double[] _times;
    private readonly int[] _masks;

    /// <summary>Parses a script.</summary>
    /// <exception cref="FormatException">A step is malformed or times do not increase.</exception>
    public ScriptedPedalSource(string script)
    {
        ArgumentNullException.ThrowIfNull(script);
        var steps = script.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries)
            .Select(step =>
            {
                var parts = step.Split(':');
                if (parts.Length != 2
                    || !double.TryParse(parts[0], NumberStyles.Float, CultureInfo.InvariantCulture, out var t)
                    || !int.TryParse(parts[1], NumberStyles.Integer, CultureInfo.InvariantCulture, out var m)
                    || m is < 0 or > 255 || !double.IsFinite(t))
                {
                    throw new FormatException($"pedal script step '{step}': expected time_s:mask, e.g. 2.5:1");
                }

                return (t, m);
            })
            .ToList();
        for (var i = 1; i < steps.Count; i++)
        {
            if (steps[i].t <= steps[i - 1].t)
            {
                throw new FormatException($"pedal script: time {steps[i].t} does not increase");
            }
        }

        _times = [.. steps.Select(s => s.t)];
        _masks = [.. steps.Select(s => s.m)];
    }

    /// <inheritdoc />
    public void Start()
    {
    }

    /// <inheritdoc />
    public int Read(double timeSeconds)
    {
        var mask = 0;
        for (var i = 0; i < _times.Length && _times[i] <= timeSeconds; i++)
        {
            mask = _masks[i];
        }

        return mask;
    }

    /// <inheritdoc />
    public void Dispose()
    {
    }
}
