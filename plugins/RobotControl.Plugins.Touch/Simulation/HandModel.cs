namespace RobotControl.Plugins.Touch.Simulation;

/// <summary>
/// The operator's hand holding the stylus: the handle (mass m) is tied to where the hand wants it by a spring k and
/// damper b, so a device force F pushes the handle away from the hand's target: m a = k (h - p) + b (h' - v) + F.
/// Integrated with semi-implicit Euler in sub-steps of at most 0.25 ms (stable for the stiffness range allowed).
/// Units: mm, mm/s, N, kg (1 N = 1000 kg mm/s²).
/// </summary>
public sealed class HandModel
{
    private const double MaxStepSeconds = 0.00025;
    private readonly double _mass;
    private readonly double _stiffness; // N/mm
    private readonly double _damping; // N s/mm
    private readonly double[] _position = new double[3];
    private readonly double[] _velocity = new double[3];

    /// <summary>Creates a hand: effective mass (kg), grip stiffness (N/mm) and damping (N s/mm).</summary>
    public HandModel(double massKg, double stiffnessNPerMm, double dampingNsPerMm)
    {
        ArgumentOutOfRangeException.ThrowIfLessThanOrEqual(massKg, 0);
        ArgumentOutOfRangeException.ThrowIfLessThanOrEqual(stiffnessNPerMm, 0);
        ArgumentOutOfRangeException.ThrowIfNegative(dampingNsPerMm);
        _mass = massKg;
        _stiffness = stiffnessNPerMm;
        _damping = dampingNsPerMm;
    }

    /// <summary>Handle position, mm.</summary>
    public ReadOnlySpan<double> Position => _position;

    /// <summary>Handle velocity, mm/s.</summary>
    public ReadOnlySpan<double> Velocity => _velocity;

    /// <summary>Places the handle at rest at <paramref name="position"/>.</summary>
    public void Reset(ReadOnlySpan<double> position)
    {
        position[..3].CopyTo(_position);
        Array.Clear(_velocity);
    }

    /// <summary>Advances by <paramref name="seconds"/> with the hand at <paramref name="hand"/> moving at <paramref name="handVelocity"/> and a device force.</summary>
    public void Step(double seconds, ReadOnlySpan<double> hand, ReadOnlySpan<double> handVelocity, double forceXN, double forceYN, double forceZN)
    {
        if (seconds <= 0)
        {
            return;
        }

        var steps = (int)Math.Ceiling(seconds / MaxStepSeconds);
        var h = seconds / steps;
        for (var s = 0; s < steps; s++)
        {
            for (var k = 0; k < 3; k++)
            {
                var force = k == 0 ? forceXN : k == 1 ? forceYN : forceZN;
                var spring = (_stiffness * (hand[k] - _position[k])) + (_damping * (handVelocity[k] - _velocity[k]));
                var accel = (spring + force) * 1000.0 / _mass; // N / kg = m/s² = 1000 mm/s²
                _velocity[k] += accel * h;
                _position[k] += _velocity[k] * h;
            }
        }
    }
}
