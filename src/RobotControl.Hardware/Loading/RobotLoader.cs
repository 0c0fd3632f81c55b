using System.Text.Json;
using RobotControl.Hardware.Json;
using RobotControl.Hardware.Model;

namespace RobotControl.Hardware.Loading;

/// <summary>
/// Loads and validates a robot data file and the component catalogues it references. Every problem is reported with
/// the file, the JSON path of the field and what is wrong; a file with any problem yields no definition at all.
/// </summary>
public static class RobotLoader
{
    /// <summary>The schema identifier robot files carry.</summary>
    public const string RobotSchema = "robotcontrol/robot/1";

    private const string MotorSchema = "robotcontrol/motors/1";
    private const string GearheadSchema = "robotcontrol/gearheads/1";
    private const double Deg = Math.PI / 180.0;

    private static readonly JsonDocumentOptions DocumentOptions = new()
    {
        AllowTrailingCommas = false,
        CommentHandling = JsonCommentHandling.Skip,
    };

    /// <summary>Loads a robot file.</summary>
    /// <exception cref="RobotDataException">The file or a catalogue it references is missing or invalid.</exception>
    public static RobotDefinition Load(string path)
    {
        ArgumentException.ThrowIfNullOrEmpty(path);
        var fullPath = System.IO.Path.GetFullPath(path);
        using var document = Parse(fullPath);
        return Read(document.RootElement, fullPath);
    }

    /// <summary>Loads a robot from JSON text (catalogue paths resolve relative to <paramref name="virtualPath"/>).</summary>
    /// <exception cref="RobotDataException">The text or a catalogue it references is invalid.</exception>
    public static RobotDefinition LoadFromText(string json, string virtualPath)
    {
        ArgumentNullException.ThrowIfNull(json);
        var fullPath = System.IO.Path.GetFullPath(virtualPath);
        JsonDocument document;
        try
        {
            document = JsonDocument.Parse(json, DocumentOptions);
        }
        catch (JsonException ex)
        {
            throw new RobotDataException([new JsonProblem("$", $"not valid JSON: {ex.Message}") { File = fullPath }]);
        }

        using (document)
        {
            return Read(document.RootElement, fullPath);
        }
    }

    private static JsonDocument Parse(string fullPath)
    {
        string text;
        try
        {
            text = File.ReadAllText(fullPath);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            throw new RobotDataException([new JsonProblem("$", $"cannot read the file: {ex.Message}") { File = fullPath }]);
        }

        try
        {
            return JsonDocument.Parse(text, DocumentOptions);
        }
        catch (JsonException ex)
        {
            throw new RobotDataException([new JsonProblem("$", $"not valid JSON: {ex.Message}") { File = fullPath }]);
        }
    }

    private static RobotDefinition Read(JsonElement root, string file)
    {
        var sink = new JsonProblemSink(file);
        var r = new JsonFieldReader(sink, root, "$");
        if (!r.IsObject)
        {
            sink.Add("$", "the file must hold a JSON object");
            RobotDataException.ThrowIfAny(sink);
        }

        var schema = r.String("schema");
        if (schema.Length > 0 && schema != RobotSchema)
        {
            sink.Add("$.schema", $"is \"{schema}\"; expected \"{RobotSchema}\"");
        }

        var name = r.String("name");
        var description = r.StringOrNull("description") ?? string.Empty;
        var crossSectionArea = r.Number("shoulder_cross_section_cm2", min: 0, max: Plausible.AreaCm2);

        // Component catalogues: problems in them are reported against their own files.
        var motors = new List<MotorDefinition>();
        var gearheads = new List<GearheadDefinition>();
        var catalogs = r.Array("component_catalogs", nonEmpty: true) ?? [];
        for (var i = 0; i < catalogs.Count; i++)
        {
            var p = $"$.component_catalogs[{i}]";
            if (catalogs[i].ValueKind != JsonValueKind.String)
            {
                sink.Add(p, "must be a path string");
                continue;
            }

            var catalogPath = System.IO.Path.GetFullPath(
                System.IO.Path.Combine(System.IO.Path.GetDirectoryName(file)!, catalogs[i].GetString()!));
            if (!File.Exists(catalogPath))
            {
                sink.Add(p, $"catalogue file not found: {catalogPath}");
                continue;
            }

            ReadCatalog(catalogPath, motors, gearheads);
        }

        var joints = ReadJoints(r, sink);
        var jointIndex = joints.Select((j, i) => (j.Name, i)).GroupBy(t => t.Name).ToDictionary(g => g.Key, g => g.First().i, StringComparer.Ordinal);
        var dh = ReadDh(r, sink, jointIndex, joints.Count);
        var positionJoints = ReadJointNameList(r.Array("position_joints", nonEmpty: true), "$.position_joints", sink, jointIndex);
        var actuators = ReadActuators(r, sink, jointIndex, joints.Count, motors, gearheads);
        var tool = ReadTool(r.Object("tool"));
        r.StringOrNull("arms_note");
        var arms = ReadArms(r, sink);
        var mirror = ReadVector(r, "mirror_plane_normal", sink);
        if (mirror is { } m && m.X * m.X + m.Y * m.Y + m.Z * m.Z < 1e-12)
        {
            sink.Add("$.mirror_plane_normal", "must not be the zero vector");
        }

        var analysis = r.Object("analysis");
        var crossSection = ReadCrossSection(analysis?.Object("cross_section"), sink, jointIndex, joints);
        analysis?.RejectUnknownFields();
        var requirements = ReadRequirements(r.Object("requirements"), sink);
        var modules = ModuleSectionReader.Read(r, actuators, arms);
        _ = r.Raw("safety", required: false); // the safety supervisor's thresholds: read by the session layer (RobotControl.Host.Safety.SafetySection)
        r.RejectUnknownFields();

        RobotDataException.ThrowIfAny(sink);
        return new RobotDefinition(
            name, description, file, crossSectionArea, joints, dh, positionJoints, actuators, tool!, arms,
            mirror!.Value, crossSection!, requirements!, motors, gearheads) { Modules = modules };
    }

    private static List<JointDefinition> ReadJoints(JsonFieldReader r, JsonProblemSink sink)
    {
        var result = new List<JointDefinition>();
        var items = r.Array("joints", nonEmpty: true) ?? [];
        var names = new HashSet<string>(StringComparer.Ordinal);
        for (var i = 0; i < items.Count; i++)
        {
            var j = new JsonFieldReader(sink, items[i], $"$.joints[{i}]");
            if (!j.IsObject)
            {
                sink.Add(j.Path, "must be an object");
                continue;
            }

            var name = j.String("name");
            if (name.Length > 0 && !names.Add(name))
            {
                sink.Add(j.FieldPath("name"), $"duplicate joint name \"{name}\"");
            }

            var symbol = j.StringOrNull("symbol") ?? name;
            var min = j.Number("min_deg", -360, 360);
            var max = j.Number("max_deg", -360, 360);
            if (double.IsFinite(min) && double.IsFinite(max) && min > max)
            {
                sink.Add(j.FieldPath("min_deg"), $"joint range has min_deg {min} > max_deg {max}");
            }

            var source = j.StringOrNull("range_source") ?? string.Empty;
            j.RejectUnknownFields();
            result.Add(new JointDefinition(name, symbol, min * Deg, max * Deg, source));
        }

        return result;
    }

    private static List<DhRow> ReadDh(JsonFieldReader r, JsonProblemSink sink, Dictionary<string, int> jointIndex, int jointCount)
    {
        var rows = new List<DhRow>();
        var items = r.Array("dh");
        if (items is { Count: 0 })
        {
            sink.Add("$.dh", "the DH table is empty");
        }

        var used = new HashSet<int>();
        for (var i = 0; i < (items?.Count ?? 0); i++)
        {
            var row = new JsonFieldReader(sink, items![i], $"$.dh[{i}]");
            if (!row.IsObject)
            {
                sink.Add(row.Path, "must be an object");
                continue;
            }

            var alpha = row.Number("alpha_deg", -360, 360);
            var a = row.Number("a_mm", -Plausible.LengthMm, Plausible.LengthMm);
            var d = row.Number("d_mm", -Plausible.LengthMm, Plausible.LengthMm);
            var offset = row.Number("theta_offset_deg", -360, 360);
            var jointRaw = row.Raw("joint", required: true);
            var index = -1;
            if (jointRaw is { ValueKind: JsonValueKind.String } js)
            {
                var jn = js.GetString()!;
                if (!jointIndex.TryGetValue(jn, out index))
                {
                    sink.Add(row.FieldPath("joint"), $"refers to joint \"{jn}\", which $.joints does not define");
                    index = -1;
                }
                else if (!used.Add(index))
                {
                    sink.Add(row.FieldPath("joint"), $"joint \"{jn}\" drives more than one DH row");
                }
            }
            else if (jointRaw is { } other && other.ValueKind != JsonValueKind.Null)
            {
                sink.Add(row.FieldPath("joint"), $"must be a joint name or null, found {JsonFieldReader.Describe(other)}");
            }

            row.RejectUnknownFields();
            rows.Add(new DhRow(alpha * Deg, a, d, offset * Deg, index));
        }

        if (items is { Count: > 0 })
        {
            for (var j = 0; j < jointCount; j++)
            {
                if (!used.Contains(j))
                {
                    sink.Add("$.dh", $"no DH row is driven by joint {j} ($.joints[{j}])");
                }
            }

            // Joint variables must appear in chain order so q[i] is the i-th joint from the base.
            var order = rows.Where(x => x.JointIndex >= 0).Select(x => x.JointIndex).ToArray();
            if (!order.SequenceEqual(order.Order()))
            {
                sink.Add("$.dh", "joints must drive DH rows in the order $.joints lists them");
            }
        }

        return rows;
    }

    private static List<int> ReadJointNameList(IReadOnlyList<JsonElement>? items, string path, JsonProblemSink sink, Dictionary<string, int> jointIndex)
    {
        var result = new List<int>();
        for (var i = 0; i < (items?.Count ?? 0); i++)
        {
            var e = items![i];
            if (e.ValueKind != JsonValueKind.String || !jointIndex.TryGetValue(e.GetString()!, out var idx))
            {
                sink.Add($"{path}[{i}]", $"must name a joint defined in $.joints, found {JsonFieldReader.Describe(e)}");
                continue;
            }

            result.Add(idx);
        }

        return result;
    }

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

    private static ToolDefinition? ReadTool(JsonFieldReader? t)
    {
        if (t is null)
        {
            return null;
        }

        var jaw = t.Object("jaw_range_deg");
        var jmin = jaw?.Number("min_deg", -360, 360) ?? double.NaN;
        var jmax = jaw?.Number("max_deg", -360, 360) ?? double.NaN;
        if (jaw is not null && jmin > jmax)
        {
            t.Sink.Add(jaw.Path, $"jaw range has min_deg {jmin} > max_deg {jmax}");
        }

        jaw?.RejectUnknownFields();
        var ls = t.Object("lead_screw");
        var dm = ls?.Number("mean_diameter_mm", min: 0, max: Plausible.LengthMm) ?? double.NaN;
        var lead = ls?.Number("lead_mm", min: 0, max: Plausible.LengthMm) ?? double.NaN;
        var angle = ls?.Number("thread_angle_deg", 0, 180) ?? double.NaN;
        var f = ls?.Number("friction_coefficient", 0, 10) ?? double.NaN;
        ls?.RejectUnknownFields();
        var link = t.Object("jaw_linkage");
        var offset = link?.Number("theta_a_offset_deg", -360, 360) ?? double.NaN;
        var l1 = link?.NumberOrNull("l1_mm", min: 0, max: Plausible.LengthMm);
        var l2 = link?.NumberOrNull("l2_mm", min: 0, max: Plausible.LengthMm);
        var l3 = link?.NumberOrNull("l3_mm", min: 0, max: Plausible.LengthMm);
        var doff = link?.NumberOrNull("d_offset_mm", -Plausible.LengthMm, Plausible.LengthMm);
        link?.StringOrNull("note");
        link?.RejectUnknownFields();
        t.RejectUnknownFields();
        return new ToolDefinition(jmin * Deg, jmax * Deg, dm, lead, angle * Deg, f, offset * Deg, l1, l2, l3, doff);
    }

    private static List<ArmPlacement> ReadArms(JsonFieldReader r, JsonProblemSink sink)
    {
        var result = new List<ArmPlacement>();
        var items = r.Array("arms", nonEmpty: true) ?? [];
        for (var i = 0; i < items.Count; i++)
        {
            var a = new JsonFieldReader(sink, items[i], $"$.arms[{i}]");
            var name = a.String("name");
            var mirrored = a.Boolean("mirrored");
            var offset = ReadVector(a, "base_offset_mm", sink);
            a.RejectUnknownFields();
            result.Add(new ArmPlacement(name, mirrored, offset ?? default));
        }

        return result;
    }

    private static Vector3Data? ReadVector(JsonFieldReader r, string name, JsonProblemSink sink)
    {
        var items = r.Array(name);
        if (items is null)
        {
            return null;
        }

        if (items.Count != 3)
        {
            sink.Add(r.FieldPath(name), $"must have 3 components, found {items.Count}");
            return null;
        }

        var v = new double[3];
        for (var i = 0; i < 3; i++)
        {
            v[i] = r.ReadNumber(items[i], $"{r.FieldPath(name)}[{i}]", -Plausible.LengthMm, Plausible.LengthMm);
        }

        return new Vector3Data(v[0], v[1], v[2]);
    }

    private static CrossSectionDefinition? ReadCrossSection(JsonFieldReader? c, JsonProblemSink sink, Dictionary<string, int> jointIndex, List<JointDefinition> joints)
    {
        if (c is null)
        {
            return null;
        }

        int Joint(string field)
        {
            var n = c.String(field);
            if (n.Length > 0 && !jointIndex.TryGetValue(n, out var idx))
            {
                sink.Add(c.FieldPath(field), $"refers to joint \"{n}\", which $.joints does not define");
                return -1;
            }

            return n.Length > 0 ? jointIndex[n] : -1;
        }

        var xj = Joint("x_joint");
        var xmin = c.Number("x_min_deg", -360, 360);
        var xmax = c.Number("x_max_deg", -360, 360);
        var yj = Joint("y_joint");
        var ymin = c.Number("y_min_deg", -360, 360);
        var ymax = c.Number("y_max_deg", -360, 360);
        var step = c.Number("step_deg", min: 1e-6, max: 90);
        if (xmin > xmax)
        {
            sink.Add(c.Path, $"x range has x_min_deg {xmin} > x_max_deg {xmax}");
        }

        if (ymin > ymax)
        {
            sink.Add(c.Path, $"y range has y_min_deg {ymin} > y_max_deg {ymax}");
        }

        var fixedRad = joints.Select(j => 0.0).ToArray();
        var fixedObj = c.Object("fixed_deg");
        if (fixedObj is not null)
        {
            foreach (var (jn, value) in fixedObj.Properties())
            {
                if (!jointIndex.TryGetValue(jn, out var ji))
                {
                    sink.Add(fixedObj.FieldPath(jn), $"refers to joint \"{jn}\", which $.joints does not define");
                    continue;
                }

                fixedRad[ji] = fixedObj.ReadNumber(value, fixedObj.FieldPath(jn), -360, 360) * Deg;
            }
        }

        var used = ReadJointNameList(c.Array("joints_used", nonEmpty: true), c.FieldPath("joints_used"), sink, jointIndex);
        c.RejectUnknownFields();
        return new CrossSectionDefinition(xj, xmin * Deg, xmax * Deg, yj, ymin * Deg, ymax * Deg, step * Deg, fixedRad, used);
    }

    private static RequirementsDefinition? ReadRequirements(JsonFieldReader? q, JsonProblemSink sink)
    {
        if (q is null)
        {
            return null;
        }

        Vector3Data Xyz(string field)
        {
            var o = q.Object(field);
            if (o is null)
            {
                return default;
            }

            var v = new Vector3Data(o.Number("x", 0, Plausible.Requirement), o.Number("y", 0, Plausible.Requirement), o.Number("z", 0, Plausible.Requirement));
            o.RejectUnknownFields();
            return v;
        }

        var force = Xyz("force_N");
        var velocity = Xyz("velocity_mm_s");
        var roll = q.Number("grasper_roll_rad_s", 0, Plausible.Requirement);
        q.StringOrNull("source");
        q.RejectUnknownFields();
        _ = sink;
        return new RequirementsDefinition(force, velocity, roll);
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
