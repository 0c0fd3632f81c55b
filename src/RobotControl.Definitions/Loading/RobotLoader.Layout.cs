using System.Text.Json;
using RobotControl.Definitions.Json;
using RobotControl.Definitions.Model;

namespace RobotControl.Definitions.Loading;

/// <summary>Robot files: tool, arm placement, analysis cross-section and requirements.</summary>
public static partial class RobotLoader
{
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
}
