using System.Text.Json;
using RobotControl.Definitions.Json;
using RobotControl.Definitions.Model;

namespace RobotControl.Definitions.Loading;

/// <summary>Robot files: actuators with their drivetrains and couplings; the motor and gearhead catalogues.</summary>
public static partial class RobotLoader
{
    private static List<ActuatorDefinition> ReadActuators(
        JsonFieldReader r, JsonProblemSink sink, Dictionary<string, int> jointIndex, int jointCount,
        List<MotorDefinition> motors, List<GearheadDefinition> gearheads)
    {
        var result = new List<ActuatorDefinition>();
        var items = r.Array("actuators", nonEmpty: true) ?? [];
        var names = new HashSet<string>(StringComparer.Ordinal);
        for (var i = 0; i < items.Count; i++)
        {
            var a = new JsonFieldReader(sink, items[i], $"$.actuators[{i}]");
            if (!a.IsObject)
            {
                sink.Add(a.Path, "must be an object");
                continue;
            }

            var name = a.String("name");
            if (name.Length > 0 && !names.Add(name))
            {
                sink.Add(a.FieldPath("name"), $"duplicate actuator name \"{name}\"");
            }

            var label = a.StringOrNull("label") ?? name;
            var joint = -1;
            string? jointName = null;
            if (a.Raw("joint", required: true) is { } jr)
            {
                if (jr.ValueKind == JsonValueKind.String)
                {
                    jointName = jr.GetString();
                }
                else if (jr.ValueKind != JsonValueKind.Null)
                {
                    sink.Add(a.FieldPath("joint"), $"must be a joint name or null, found {JsonFieldReader.Describe(jr)}");
                }
            }

            if (jointName is not null && !jointIndex.TryGetValue(jointName, out joint))
            {
                sink.Add(a.FieldPath("joint"), $"refers to joint \"{jointName}\", which $.joints does not define");
                joint = -1;
            }

            var coupling = new double[jointCount];
            var c = a.Object("coupling", required: jointName is not null);
            if (c is not null)
            {
                foreach (var (jn, value) in c.Properties())
                {
                    if (!jointIndex.TryGetValue(jn, out var ji))
                    {
                        sink.Add(c.FieldPath(jn), $"refers to joint \"{jn}\", which $.joints does not define");
                        continue;
                    }

                    coupling[ji] = c.ReadNumber(value, c.FieldPath(jn), -Plausible.Coupling, Plausible.Coupling);
                }

                if (coupling.All(x => x == 0))
                {
                    sink.Add(a.FieldPath("coupling"), "must give a non-zero coefficient for at least one joint");
                }
            }

            var d = a.Object("drivetrain");
            DrivetrainDefinition? drivetrain = null;
            if (d is not null)
            {
                var n = d.Integer("meshes_after_gearhead", 0, 20);
                var outTeeth = d.Integer("stage_output_teeth", 1, 100000);
                var inTeeth = d.Integer("stage_input_teeth", 1, 100000);
                var series = d.String("gearhead_series");
                var ratio = d.Number("gearhead_ratio", min: 1, max: Plausible.Ratio);
                var eff = d.Number("gearhead_efficiency_pct", 0, 100);
                var motor = d.String("motor");
                var note = d.StringOrNull("note");
                d.RejectUnknownFields();
                // Checked even when no motor catalogue loaded: a dangling reference must not pass validation.
                if (motor.Length > 0 && motors.All(m => m.Model != motor))
                {
                    sink.Add(d.FieldPath("motor"), $"refers to motor \"{motor}\", which no component catalogue defines (known: {string.Join(", ", motors.Select(m => m.Model))})");
                }

                var gearhead = gearheads.FirstOrDefault(g => g.Series == series);
                if (series.Length > 0 && gearhead is null)
                {
                    sink.Add(d.FieldPath("gearhead_series"), $"refers to gearhead series \"{series}\", which no component catalogue defines");
                }
                else if (gearhead is not null && double.IsFinite(ratio) && gearhead.Stages.All(s => Math.Abs(s.Ratio - ratio) > 1e-9))
                {
                    sink.Add(d.FieldPath("gearhead_ratio"), $"{ratio}:1 is not a ratio of gearhead series {series} ({string.Join(", ", gearhead.Stages.Select(s => s.Ratio))})");
                }

                drivetrain = new DrivetrainDefinition(n, outTeeth, inTeeth, series, ratio, eff / 100.0, motor, note);
            }

            a.RejectUnknownFields();
            result.Add(new ActuatorDefinition(name, label, joint, coupling, drivetrain!));
        }

        // The coupling must be invertible over the kinematic joints so joint <-> motor mapping works both ways.
        var kinematic = result.Where(x => x.IsKinematic).ToList();
        if (kinematic.Count != jointCount)
        {
            sink.Add("$.actuators", $"{kinematic.Count} actuators drive kinematic joints but there are {jointCount} joints; each joint needs one");
        }
        else if (!CouplingIsInvertible(kinematic.Select(x => x.Coupling).ToArray()))
        {
            sink.Add("$.actuators", "the coupling coefficients of the kinematic actuators form a singular matrix: joint angles could not be recovered from motor angles");
        }

        foreach (var duplicate in kinematic.GroupBy(x => x.JointIndex).Where(g => g.Count() > 1))
        {
            var i = result.IndexOf(duplicate.Last());
            sink.Add($"$.actuators[{i}].joint", $"joint {duplicate.Key} ($.joints[{duplicate.Key}]) is already listed against actuator \"{duplicate.First().Name}\"");
        }

        return result;
    }

    /// <summary>Gaussian elimination with partial pivoting: true when the square coupling matrix is well invertible.</summary>
    private static bool CouplingIsInvertible(IReadOnlyList<double>[] rows)
    {
        var n = rows.Length;
        if (n == 0)
        {
            return true; // no joints: the missing joints are reported elsewhere
        }

        if (rows.Any(r => r.Count != n || r.Any(v => !double.IsFinite(v))))
        {
            return true; // a bad coefficient is reported where it stands
        }

        var m = rows.Select(r => r.ToArray()).ToArray();
        var scale = m.Max(r => r.Max(Math.Abs));
        for (var col = 0; col < n; col++)
        {
            var pivot = col;
            for (var r = col + 1; r < n; r++)
            {
                if (Math.Abs(m[r][col]) > Math.Abs(m[pivot][col]))
                {
                    pivot = r;
                }
            }

            if (Math.Abs(m[pivot][col]) <= 1e-9 * scale)
            {
                return false;
            }

            (m[col], m[pivot]) = (m[pivot], m[col]);
            for (var r = col + 1; r < n; r++)
            {
                var f = m[r][col] / m[col][col];
                for (var c = col; c < n; c++)
                {
                    m[r][c] -= f * m[col][c];
                }
            }
        }

        return true;
    }

    private static void ReadCatalog(string path, List<MotorDefinition> motors, List<GearheadDefinition> gearheads)
    {
        using var doc = Parse(path);
        var sink = new JsonProblemSink(path);
        var r = new JsonFieldReader(sink, doc.RootElement, "$");
        var schema = r.String("schema");
        r.StringOrNull("source");
        if (schema == MotorSchema)
        {
            var items = r.Array("motors", nonEmpty: true) ?? [];
            for (var i = 0; i < items.Count; i++)
            {
                var m = new JsonFieldReader(sink, items[i], $"$.motors[{i}]");
                m.StringOrNull("kind");
                var motor = new MotorDefinition(
                    m.String("model"),
                    m.Integer("pole_pairs", 1, 64),
                    m.Number("nominal_voltage_V", 0, Plausible.CatalogueValue),
                    m.Number("terminal_resistance_ohm", 0, Plausible.CatalogueValue),
                    m.Number("no_load_speed_rpm", 0, Plausible.CatalogueValue),
                    m.Number("no_load_current_A", 0, Plausible.CatalogueValue),
                    m.Number("stall_torque_mNm", 0, Plausible.CatalogueValue),
                    m.Number("static_friction_torque_mNm", 0, Plausible.CatalogueValue),
                    m.Number("dynamic_friction_mNm_per_rpm", 0, Plausible.CatalogueValue),
                    m.Number("speed_constant_rpm_per_V", 0, Plausible.CatalogueValue),
                    m.Number("back_emf_constant_mV_per_rpm", 0, Plausible.CatalogueValue),
                    m.Number("torque_constant_mNm_per_A", 0, Plausible.CatalogueValue),
                    m.Number("terminal_inductance_uH", 0, Plausible.CatalogueValue),
                    m.Number("mechanical_time_constant_ms", 0, Plausible.CatalogueValue),
                    m.Number("rotor_inertia_g_cm2", 0, Plausible.CatalogueValue),
                    m.Number("rated_torque_mNm", 0, Plausible.CatalogueValue),
                    m.Number("rated_current_A", 0, Plausible.CatalogueValue),
                    m.Number("rated_speed_rpm", 0, Plausible.CatalogueValue),
                    m.Number("max_speed_rpm", 0, Plausible.CatalogueValue),
                    m.Number("mass_g", 0, Plausible.MassG),
                    m.Number("max_winding_temperature_C", Plausible.MinTemperatureC, Plausible.MaxTemperatureC),
                    m.Number("thermal_resistance_winding_housing_K_per_W", 0, Plausible.CatalogueValue),
                    m.Number("thermal_resistance_housing_ambient_K_per_W", 0, Plausible.CatalogueValue),
                    m.Number("thermal_time_constant_winding_s", 0, Plausible.CatalogueValue),
                    m.Number("thermal_time_constant_housing_s", 0, Plausible.CatalogueValue));
                m.Number("max_efficiency_pct", 0, 100);
                m.RejectUnknownFields();
                motors.Add(motor);
            }
        }
        else if (schema == GearheadSchema)
        {
            var items = r.Array("gearheads", nonEmpty: true) ?? [];
            for (var i = 0; i < items.Count; i++)
            {
                var g = new JsonFieldReader(sink, items[i], $"$.gearheads[{i}]");
                var stages = new List<GearheadStage>();
                var stageItems = g.Array("stages", nonEmpty: true) ?? [];
                for (var s = 0; s < stageItems.Count; s++)
                {
                    var st = new JsonFieldReader(sink, stageItems[s], $"{g.Path}.stages[{s}]");
                    stages.Add(new GearheadStage(st.Number("ratio", min: 1, max: Plausible.Ratio), st.Number("efficiency_pct", 0, 100) / 100.0));
                    st.RejectUnknownFields();
                }

                gearheads.Add(new GearheadDefinition(
                    g.String("series"),
                    g.String("for_motor"),
                    g.Number("continuous_output_torque_mNm", 0, Plausible.CatalogueValue),
                    g.Number("intermittent_output_torque_mNm", 0, Plausible.CatalogueValue),
                    g.Number("max_input_speed_rpm", 0, Plausible.CatalogueValue),
                    g.Number("backlash_deg", 0, Plausible.CatalogueValue),
                    stages));
                g.RejectUnknownFields();
            }
        }
        else
        {
            sink.Add("$.schema", $"is \"{schema}\"; expected \"{MotorSchema}\" or \"{GearheadSchema}\"");
        }

        r.RejectUnknownFields();
        RobotDataException.ThrowIfAny(sink);
    }
}
