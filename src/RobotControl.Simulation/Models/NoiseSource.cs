namespace RobotControl.Simulation.Models;

/// <summary>Seeded Gaussian noise (Box-Muller), so simulated sensor readings repeat exactly.</summary>
public sealed class NoiseSource
{
    private readonly Random _random;
    private double _spare;
    private bool _hasSpare;

    /// <summary>Creates a source with <paramref name="seed"/>.</summary>
    public NoiseSource(int seed)
    {
#pragma warning disable CA5394 // simulation noise, not security
        _random = new Random(seed);
    }

    /// <summary>A uniform sample in [0, 1).</summary>
    public double Uniform() => _random.NextDouble();
#pragma warning restore CA5394

    /// <summary>A normal sample with standard deviation <paramref name="sigma"/>.</summary>
    public double Gaussian(double sigma)
    {
        if (_hasSpare)
        {
            _hasSpare = false;
            return _spare * sigma;
        }

        double u, v, s;
        do
        {
            u = (2 * Uniform()) - 1;
            v = (2 * Uniform()) - 1;
            s = (u * u) + (v * v);
        }
        while (s is >= 1 or 0);

        var f = Math.Sqrt(-2 * Math.Log(s) / s);
        _spare = v * f;
        _hasSpare = true;
        return u * f * sigma;
    }
}
