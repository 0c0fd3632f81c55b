namespace RobotControl.Simulation.Models;

/// <summary>Digital Hall sensors of a BLDC motor: the 3-bit code of the rotor's electrical sector.</summary>
public static class HallSensors
{
    // Codes for sectors 0..5 of the electrical revolution, H1 in bit 0 (120-degree spacing).
    private static readonly byte[] Sequence = [0b001, 0b011, 0b010, 0b110, 0b100, 0b101];

    /// <summary>The Hall code (1..6) for rotor angle <paramref name="rotorAngleRad"/> with <paramref name="polePairs"/>.</summary>
    public static byte Code(double rotorAngleRad, int polePairs)
    {
        var electrical = rotorAngleRad * polePairs / (Math.PI / 3);
        var sector = (long)Math.Floor(electrical) % 6;
        return Sequence[sector < 0 ? sector + 6 : sector];
    }

    /// <summary>The code sequence in the positive direction.</summary>
    public static ReadOnlySpan<byte> PositiveSequence => Sequence;
}
