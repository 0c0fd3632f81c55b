using System.Text.Json;
using RobotControl.Definitions.Json;
using RobotControl.Runtime.Robot;

namespace RobotControl.Runtime.GraphFiles;

/// <summary>Where the graph editor draws one node (editor-only: the loop never reads it).</summary>
/// <param name="X">Left edge, editor pixels.</param>
/// <param name="Y">Top edge, editor pixels.</param>
public sealed record NodePosition(double X, double Y);

/// <summary>
/// The optional <c>layout</c> field of a graph file: the graph editor's node positions,
/// <c>"layout": { "clutch_right": { "x": 420, "y": 80 }, "robot": { "x": 900, "y": 40 } }</c>. It changes nothing the
/// loop does, but is checked as strictly as the rest: each key names an instance of the file (or <c>robot</c>), each
/// value holds exactly the numbers <c>x</c> and <c>y</c>.
/// </summary>
internal static class GraphLayout
{
    public const string Field = "layout";

    /// <summary>Reads <c>$.layout</c> (null when absent), reporting every problem.</summary>
    public static IReadOnlyDictionary<string, NodePosition>? Read(JsonElement root, IReadOnlySet<string> instanceNames, bool hasRobot, JsonProblemSink problems)
    {
        if (!root.TryGetProperty(Field, out var layout))
        {
            return null;
        }

        if (layout.ValueKind != JsonValueKind.Object)
        {
            problems.Add("$.layout", "expected an object of node positions: { \"<instance>\": { \"x\": <number>, \"y\": <number> } }");
            return null;
        }

        var positions = new Dictionary<string, NodePosition>(StringComparer.Ordinal);
        foreach (var entry in layout.EnumerateObject())
        {
            var at = $"$.layout.{entry.Name}";
            if (!instanceNames.Contains(entry.Name) && !(hasRobot && entry.Name == RobotNode.InstanceName))
            {
                problems.Add(at, $"no instance named '{entry.Name}' in $.instances");
                continue;
            }

            var fields = new JsonFieldReader(problems, entry.Value, at, JsonWording.Brief);
            if (!fields.IsObject)
            {
                problems.Add(at, "expected an object with the numbers x and y");
                continue;
            }

            fields.RejectFieldsOtherThan("x", "y");
            var x = fields.Number("x");
            var y = fields.Number("y");
            if (double.IsFinite(x) && double.IsFinite(y))
            {
                positions[entry.Name] = new NodePosition(x, y);
            }
        }

        return positions;
    }

    /// <summary>Writes <c>layout</c> (positions rounded to whole pixels, in the dictionary's order).</summary>
    public static void Write(Utf8JsonWriter writer, IReadOnlyDictionary<string, NodePosition> layout)
    {
        writer.WriteStartObject(Field);
        foreach (var (name, position) in layout)
        {
            writer.WriteStartObject(name);
            writer.WriteNumber("x", Math.Round(position.X));
            writer.WriteNumber("y", Math.Round(position.Y));
            writer.WriteEndObject();
        }

        writer.WriteEndObject();
    }
}
