namespace RobotControl.Plugins.Touch;

/// <summary>
/// The stylus tip's speed implied by two successive readings, mm/s, in the device frame before any scaling: the
/// distance between the positions over the time between the readings' own instants (the tick's time less the
/// reading's age, so a reading repeated by a device slower than the loop is not a new one), that time never taken as
/// shorter than <see cref="MinIntervalSeconds"/> (the device's 1 kHz servo period), so that two ticks bunched up by a
/// late loop do not make an ordinary move look fast. The first reading gives 0; a repeated one gives the last speed; a
/// non-finite position gives NaN (implausible).
/// </summary>
internal sealed class TipSpeed
{
    /// <summary>The shortest time between two readings taken for a speed, seconds.</summary>
    public const double MinIntervalSeconds = 1e-3;

    private double _x;
    private double _y;
    private double _z;
    private double _t = double.NaN;
    private double _speed;

    /// <summary>The speed from the previous reading to this one (taken at <paramref name="timeSeconds"/>).</summary>
    public double Speed(double timeSeconds, double xMm, double yMm, double zMm)
    {
        if (!double.IsFinite(xMm) || !double.IsFinite(yMm) || !double.IsFinite(zMm))
        {
            return double.NaN;
        }

        if (timeSeconds == _t)
        {
            return _speed; // the same reading again
        }

        var first = double.IsNaN(_t);
        var dx = xMm - _x;
        var dy = yMm - _y;
        var dz = zMm - _z;
        var interval = Math.Max(timeSeconds - _t, MinIntervalSeconds);
        _x = xMm;
        _y = yMm;
        _z = zMm;
        _t = timeSeconds;
        _speed = first ? 0 : Math.Sqrt((dx * dx) + (dy * dy) + (dz * dz)) / interval;
        return _speed;
    }
}
