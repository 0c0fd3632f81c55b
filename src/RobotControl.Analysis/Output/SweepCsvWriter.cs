using System.Globalization;
using System.Text;

namespace RobotControl.Analysis.Output;

/// <summary>
/// Writes <c>sweep.csv</c>: one row per grid point (x joint outer, y joint inner) with every joint value (deg), the
/// tool position (mm), manipulability raw (mm³) and normalised, vx vy vz (mm/s) and fx fy fz (N), then the
/// coupling-aware velocity and force columns (prefix <c>ca_</c>) when computed.
/// </summary>
public static class SweepCsvWriter
{
    /// <summary>Serialises the sweep of <paramref name="report"/> as UTF-8 CSV.</summary>
    public static byte[] Write(AnalysisReport report)
    {
        ArgumentNullException.ThrowIfNull(report);
        var sweep = report.Sweep;
        var robot = report.Robot;
        var inv = CultureInfo.InvariantCulture;
        var sb = new StringBuilder(sweep.Count * 160);
        var header = robot.Joints.Select(j => j.Name + "_deg")
            .Concat(["x_mm", "y_mm", "z_mm", "manipulability_mm3", "manipulability_normalised", "vx_mm_s", "vy_mm_s", "vz_mm_s", "fx_N", "fy_N", "fz_N"]);
        if (sweep.CouplingAware is not null)
        {
            header = header.Concat(["ca_vx_mm_s", "ca_vy_mm_s", "ca_vz_mm_s", "ca_fx_N", "ca_fy_N", "ca_fz_N"]);
        }

        sb.Append(string.Join(',', header)).Append('\n');
        var q = new double[robot.JointCount];
        for (var i = 0; i < sweep.Count; i++)
        {
            sweep.JointsAt(i, q);
            foreach (var value in q)
            {
                sb.Append((value * 180.0 / Math.PI).ToString("0.######", inv)).Append(',');
            }

            for (var a = 0; a < 3; a++)
            {
                sb.Append(sweep.Position[a][i].ToString("0.####", inv)).Append(',');
            }

            sb.Append(sweep.Manipulability[i].ToString("G7", inv)).Append(',');
            sb.Append(sweep.ManipulabilityNormalised[i].ToString("0.######", inv));
            AppendMaps(sb, sweep.Reference, i, inv);
            if (sweep.CouplingAware is not null)
            {
                AppendMaps(sb, sweep.CouplingAware, i, inv);
            }

            sb.Append('\n');
        }

        return Encoding.UTF8.GetBytes(sb.ToString());
    }

    private static void AppendMaps(StringBuilder sb, Sweep.CapabilityMaps maps, int i, CultureInfo inv)
    {
        for (var a = 0; a < 3; a++)
        {
            sb.Append(',').Append(maps.Velocity[a][i].ToString("0.###", inv));
        }

        for (var a = 0; a < 3; a++)
        {
            sb.Append(',').Append(maps.Force[a][i].ToString("0.0", inv));
        }
    }
}
