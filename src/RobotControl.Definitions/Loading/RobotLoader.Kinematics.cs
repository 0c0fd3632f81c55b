using System.Text.Json;
using RobotControl.Definitions.Json;
using RobotControl.Definitions.Model;

namespace RobotControl.Definitions.Loading;

/// <summary>Robot files: joints, the DH table and joint-name lists.</summary>
public static partial class RobotLoader
{
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
}
