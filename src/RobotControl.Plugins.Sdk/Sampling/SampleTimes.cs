namespace RobotControl.Plugins.Sdk.Sampling;

/// <summary>
/// Lookup in the ascending sample times of a recording or script, for per-tick sampling at steadily advancing time.
/// </summary>
public static class SampleTimes
{
    /// <summary>
    /// The last index i with <c>times[i] &lt;= t</c>; 0 when <paramref name="t"/> precedes every sample.
    /// <paramref name="hint"/> is where the previous search ended: the search walks forward from it, so advancing time
    /// costs O(1) per call, and restarts from the first sample when time went back. Allocation-free.
    /// </summary>
    /// <exception cref="ArgumentException"><paramref name="times"/> is empty.</exception>
    public static int IndexAtOrBefore(ReadOnlySpan<double> times, double t, ref int hint)
    {
        if (times.IsEmpty)
        {
            throw new ArgumentException("no sample times", nameof(times));
        }

        var i = Math.Clamp(hint, 0, times.Length - 1);
        if (times[i] > t)
        {
            i = 0;
        }

        while (i < times.Length - 1 && times[i + 1] <= t)
        {
            i++;
        }

        hint = i;
        return i;
    }
}
