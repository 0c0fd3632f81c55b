namespace RobotControl.Definitions.Loading;

/// <summary>
/// Physical plausibility limits of the robot and catalogue files, beyond which a value is a typo (e.g.
/// <c>d_mm: 1e300</c>) that would turn the kinematics and the reports into infinities. Generous for any bench or
/// surgical robot; the loader refuses values beyond them with the field's path.
/// </summary>
internal static class Plausible
{
    /// <summary>Largest link length, offset, diameter or lead, mm (10 m).</summary>
    public const double LengthMm = 10_000;

    /// <summary>Largest area, cm².</summary>
    public const double AreaCm2 = 10_000;

    /// <summary>Largest reduction ratio of a gearhead or a gear stage.</summary>
    public const double Ratio = 1_000_000;

    /// <summary>Largest magnitude of a coupling coefficient (motor turns per joint turn).</summary>
    public const double Coupling = 1_000;

    /// <summary>Largest mass, g (100 kg).</summary>
    public const double MassG = 100_000;

    /// <summary>Largest force requirement, N, and velocity requirement, mm/s.</summary>
    public const double Requirement = 1_000_000;

    /// <summary>Largest magnitude of any other catalogue value (speeds, torques, currents, constants, times).</summary>
    public const double CatalogueValue = 1e9;

    /// <summary>Winding temperature range, °C.</summary>
    public const double MinTemperatureC = -273.15, MaxTemperatureC = 1_000;
}
