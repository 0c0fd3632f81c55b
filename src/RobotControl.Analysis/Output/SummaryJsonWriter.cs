using System.Text.Json;
using RobotControl.Analysis.Sweep;

namespace RobotControl.Analysis.Output;

/// <summary>
/// Writes <c>summary.json</c>: <c>robot</c>, <c>drivetrain</c> (every actuator in file order), <c>sweep</c> (joints,
/// points, velocity_mm_s / force_N mean-min-max per axis, manipulability, requirements), <c>coupling_aware</c> (when
/// computed), <c>workspace_cm3</c> {arm, union, shared} (plus the method and raw results) and <c>current_limits</c>.
/// </summary>
public static class SummaryJsonWriter
{
    private const double Deg = 180.0 / Math.PI;
    private static readonly string[] Axes = ["x", "y", "z"];

    /// <summary>Serialises <paramref name="report"/> as indented UTF-8 JSON.</summary>
    public static byte[] Write(AnalysisReport report)
    {
        ArgumentNullException.ThrowIfNull(report);
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            var robot = report.Robot;
            var sweep = report.Sweep;
            var spec = sweep.Specification;
            w.WriteStartObject();
            w.WriteString("robot", robot.Name);
            w.WriteString("robot_file", robot.SourceFile);

            w.WriteStartArray("drivetrain");
            foreach (var d in report.Drivetrain)
            {
                w.WriteStartObject();
                w.WriteString("joint", d.Joint ?? d.Actuator);
                w.WriteString("actuator", d.Actuator);
                Number(w, "torque_mNm", d.TorqueMNm);
                Number(w, "speed_rpm", d.SpeedRpm);
                Number(w, "speed_rad_s", d.SpeedRadPerS);
                w.WriteEndObject();
            }

            w.WriteEndArray();

            w.WriteStartObject("sweep");
            w.WriteStartArray("joints");
            w.WriteStringValue(robot.Joints[spec.XJoint].Name);
            w.WriteStringValue(robot.Joints[spec.YJoint].Name);
            w.WriteEndArray();
            w.WriteNumber("points", sweep.Count);
            w.WriteStartObject("grid");
            Range(w, robot.Joints[spec.XJoint].Name, spec.XMinRad, spec.XAt(spec.XCount - 1), spec.XCount);
            Range(w, robot.Joints[spec.YJoint].Name, spec.YMinRad, spec.YAt(spec.YCount - 1), spec.YCount);
            Number(w, "step_deg", spec.StepRad * Deg);
            w.WriteStartObject("fixed_deg");
            for (var j = 0; j < robot.JointCount; j++)
            {
                if (j != spec.XJoint && j != spec.YJoint)
                {
                    Number(w, robot.Joints[j].Name, spec.FixedRad[j] * Deg);
                }
            }

            w.WriteEndObject();
            w.WriteStartArray("joints_used");
            foreach (var j in spec.JointsUsed)
            {
                w.WriteStringValue(robot.Joints[j].Name);
            }

            w.WriteEndArray();
            w.WriteEndObject();
            w.WriteString("method", "reference design: independent per-joint speed and torque of the drive listed against each joint; couplings ignored");
            Maps(w, sweep.Reference);
            w.WriteStartObject("manipulability");
            var m = Statistics.Of(sweep.Manipulability);
            Number(w, "mean", m.Mean);
            Number(w, "min", m.Min);
            Number(w, "max", m.Max);
            w.WriteString("units", "mm^3 (sqrt(det(J J^T)) of the used joints' 3 x n position Jacobian, mm/rad)");
            w.WriteEndObject();
            Requirements(w, report.Requirements, report.GrasperRoll);
            w.WriteEndObject();

            if (sweep.CouplingAware is not null && report.CouplingAwareRequirements is not null)
            {
                w.WriteStartObject("coupling_aware");
                w.WriteString("method", "speed and torque limits applied to the actuators (s = C q, tau_joint = C^T tau_act) over the used joints");
                w.WriteStartArray("actuators");
                foreach (var a in report.CouplingAwareActuators ?? [])
                {
                    w.WriteStringValue(a);
                }

                w.WriteEndArray();
                Maps(w, sweep.CouplingAware);
                Requirements(w, report.CouplingAwareRequirements, null);
                w.WriteEndObject();
            }

            if (report.Workspace is { } ws)
            {
                w.WriteStartObject("workspace_cm3");
                Number(w, "arm", ws.ArmCm3);
                Number(w, "union", ws.UnionCm3);
                Number(w, "shared", ws.SharedCm3);
                w.WriteString(
                    "method",
                    "tool-tip positions marched over the position joints (steps move the tip < h/2), marked in cylindrical cells " +
                    "about the first joint's axis and swept over its range; arms placed by mirror plane and base offsets; " +
                    "voxel centres of one cubic grid tested for union and shared; reported value = 2 V(h) - V(2h)");
                w.WriteStartArray("raw");
                foreach (var g in new[] { ws.Fine, ws.Coarse })
                {
                    w.WriteStartObject();
                    Number(w, "voxel_mm", g.VoxelMm);
                    Number(w, "arm", g.ArmCm3);
                    Number(w, "union", g.UnionCm3);
                    Number(w, "shared", g.SharedCm3);
                    Number(w, "arm_cylindrical", g.ArmCylindricalCm3);
                    w.WriteNumber("samples", g.Samples);
                    w.WriteEndObject();
                }

                w.WriteEndArray();
                w.WriteEndObject();
            }

            w.WriteStartArray("current_limits");
            foreach (var c in report.CurrentLimits)
            {
                w.WriteStartObject();
                w.WriteString("joint", c.Joint ?? c.Actuator);
                w.WriteString("actuator", c.Actuator);
                w.WriteString("gearhead", c.GearheadSeries);
                Number(w, "continuous_current_A", c.ContinuousCurrentA);
                Number(w, "intermittent_current_A", c.IntermittentCurrentA);
                Number(w, "stall_current_A", c.StallCurrentA);
                Number(w, "continuous_rating_mNm", c.ContinuousRatingMNm);
                Number(w, "intermittent_rating_mNm", c.IntermittentRatingMNm);
                Number(w, "stall_torque_at_gearhead_mNm", c.StallTorqueAtGearheadMNm);
                w.WriteBoolean("limit_needed", c.StallExceedsContinuousRating);
                Number(w, "gearhead_max_input_rpm", c.MaxInputSpeedRpm);
                Number(w, "motor_no_load_rpm", c.MotorNoLoadSpeedRpm);
                if (c.JointSpeedLimitRpm is { } limit)
                {
                    Number(w, "joint_speed_limit_rpm", limit);
                    Number(w, "joint_speed_limit_rad_s", limit * 2 * Math.PI / 60);
                }
                else
                {
                    w.WriteNull("joint_speed_limit_rpm");
                }

                w.WriteEndObject();
            }

            w.WriteEndArray();
            w.WriteEndObject();
        }

        return stream.ToArray();
    }

    private static void Maps(Utf8JsonWriter w, CapabilityMaps maps)
    {
        Triple(w, "velocity_mm_s", maps.Velocity);
        Triple(w, "force_N", maps.Force);
    }

    private static void Triple(Utf8JsonWriter w, string name, double[][] axes)
    {
        var stats = axes.Select(a => Statistics.Of(a)).ToArray();
        w.WriteStartObject(name);
        Array(w, "mean", stats.Select(s => s.Mean));
        Array(w, "min", stats.Select(s => s.Min));
        Array(w, "max", stats.Select(s => s.Max));
        w.WriteEndObject();
    }

    private static void Requirements(Utf8JsonWriter w, RequirementReport r, GrasperRollCheck? roll)
    {
        w.WriteStartObject("requirements");
        Axis(w, "force_N", r.ForceRequiredN, r.ForceFractionMet);
        Axis(w, "velocity_mm_s", r.VelocityRequiredMmPerS, r.VelocityFractionMet);
        Number(w, "all_fraction_met", r.AllFractionMet);
        if (roll is not null)
        {
            w.WriteStartObject("grasper_roll_rad_s");
            w.WriteString("joint", roll.Joint);
            Number(w, "required", roll.RequiredRadPerS);
            Number(w, "available", roll.AvailableRadPerS);
            w.WriteBoolean("met", roll.Met);
            w.WriteEndObject();
        }

        w.WriteEndObject();
    }

    private static void Axis(Utf8JsonWriter w, string name, IReadOnlyList<double> required, IReadOnlyList<double> fraction)
    {
        w.WriteStartObject(name);
        for (var a = 0; a < 3; a++)
        {
            w.WriteStartObject(Axes[a]);
            Number(w, "required", required[a]);
            Number(w, "fraction_met", fraction[a]);
            w.WriteEndObject();
        }

        w.WriteEndObject();
    }

    private static void Range(Utf8JsonWriter w, string joint, double min, double max, int count)
    {
        w.WriteStartObject(joint);
        Number(w, "min_deg", min * Deg);
        Number(w, "max_deg", max * Deg);
        w.WriteNumber("count", count);
        w.WriteEndObject();
    }

    private static void Array(Utf8JsonWriter w, string name, IEnumerable<double> values)
    {
        w.WriteStartArray(name);
        foreach (var v in values)
        {
            w.WriteNumberValue(Round(v));
        }

        w.WriteEndArray();
    }

    private static void Number(Utf8JsonWriter w, string name, double value) => w.WriteNumber(name, Round(value));

    // Six significant digits: far beyond the data's accuracy, and readable. Round-off residue (e.g. the speed along a
    // straight arm, 1e-13 mm/s) is written as 0.
    private static double Round(double value) =>
        Math.Abs(value) < 1e-9 || !double.IsFinite(value) ? (double.IsFinite(value) ? 0 : value) : Math.Round(value, Math.Clamp(5 - (int)Math.Floor(Math.Log10(Math.Abs(value))), 0, 15));
}
