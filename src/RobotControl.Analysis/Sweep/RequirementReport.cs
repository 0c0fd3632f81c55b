using RobotControl.Definitions.Model;

namespace RobotControl.Analysis.Sweep;

/// <summary>Which share of the swept points meets each force and velocity requirement.</summary>
/// <param name="ForceRequiredN">Required force along X, Y, Z, N.</param>
/// <param name="ForceFractionMet">Fraction of points (0..1) whose force along X, Y, Z reaches the requirement.</param>
/// <param name="VelocityRequiredMmPerS">Required speed along X, Y, Z, mm/s.</param>
/// <param name="VelocityFractionMet">Fraction of points whose speed along X, Y, Z reaches the requirement.</param>
/// <param name="AllFractionMet">Fraction of points meeting all six at once.</param>
public sealed record RequirementReport(
    IReadOnlyList<double> ForceRequiredN,
    IReadOnlyList<double> ForceFractionMet,
    IReadOnlyList<double> VelocityRequiredMmPerS,
    IReadOnlyList<double> VelocityFractionMet,
    double AllFractionMet)
{
    /// <summary>Checks <paramref name="maps"/> against <paramref name="requirements"/>.</summary>
    public static RequirementReport Evaluate(CapabilityMaps maps, RequirementsDefinition requirements)
    {
        ArgumentNullException.ThrowIfNull(maps);
        ArgumentNullException.ThrowIfNull(requirements);
        double[] force = [requirements.ForceN.X, requirements.ForceN.Y, requirements.ForceN.Z];
        double[] velocity = [requirements.VelocityMmPerS.X, requirements.VelocityMmPerS.Y, requirements.VelocityMmPerS.Z];
        var n = maps.Force[0].Length;
        var forceMet = new int[3];
        var velocityMet = new int[3];
        var allMet = 0;
        for (var i = 0; i < n; i++)
        {
            var all = true;
            for (var a = 0; a < 3; a++)
            {
                // The force map sits on a 0.1 N grid; a tiny tolerance keeps 0.8 on the grid counted as meeting 0.8.
                var f = maps.Force[a][i] >= force[a] - 1e-9;
                var v = maps.Velocity[a][i] >= velocity[a];
                forceMet[a] += f ? 1 : 0;
                velocityMet[a] += v ? 1 : 0;
                all &= f && v;
            }

            allMet += all ? 1 : 0;
        }

        return new RequirementReport(
            force,
            forceMet.Select(c => (double)c / n).ToArray(),
            velocity,
            velocityMet.Select(c => (double)c / n).ToArray(),
            (double)allMet / n);
    }
}
