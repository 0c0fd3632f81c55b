using System.Text.Json;
using RobotControl.Definitions.Json;
using RobotControl.Definitions.Model;

namespace RobotControl.Definitions.Loading;

/// <summary>
/// Loads and validates a robot data file and the component catalogues it references. Every problem is reported with
/// the file, the JSON path of the field and what is wrong; a file with any problem yields no definition at all.
/// </summary>
public static partial class RobotLoader
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
        var safety = SafetySectionReader.Read(r, modules, SafetySectionReader.MotorNames(modules, arms, actuators, joints));
        r.RejectUnknownFields();

        RobotDataException.ThrowIfAny(sink);
        return new RobotDefinition(
            name, description, file, crossSectionArea, joints, dh, positionJoints, actuators, tool!, arms,
            mirror!.Value, crossSection!, requirements!, motors, gearheads) { Modules = modules, Safety = safety };
    }
}
