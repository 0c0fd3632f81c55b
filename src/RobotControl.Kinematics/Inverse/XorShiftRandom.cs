namespace RobotControl.Kinematics.Inverse;

/// <summary>
/// Marsaglia's xorshift64* generator: deterministic restart seeds without allocating (System.Random is a heap object and
/// its sequence is not specified across runtime versions).
/// </summary>
internal struct XorShiftRandom
{
    private ulong _state;

    internal XorShiftRandom(ulong seed) => _state = seed == 0 ? 0x9E3779B97F4A7C15UL : seed;

    /// <summary>Uniform in [0, 1).</summary>
    internal double NextDouble()
    {
        _state ^= _state >> 12;
        _state ^= _state << 25;
        _state ^= _state >> 27;
        return ((_state * 0x2545F4914F6CDD1DUL) >> 11) * (1.0 / (1UL << 53));
    }
}
