using System.Text.Json.Nodes;
using RobotControl.Definitions.Json;
using RobotControl.Definitions.Loading;

namespace RobotControl.Definitions.Tests.Loading;

public sealed class InvalidRobotFileTests : IDisposable
{
    private readonly RobotFiles _files = new();

    public void Dispose() => _files.Dispose();

    [Fact]
    public void An_unedited_copy_loads()
    {
        var path = _files.Write(RobotFiles.Json("crb-1.0.json"));
        Assert.Equal("CRB-1.0", RobotLoader.Load(path).Name);
    }

    [Theory]
    [InlineData("crb-1.0.json")]
    [InlineData("lb-1.0.json")]
    public void Missing_field_is_named(string file)
    {
        var json = RobotFiles.Json(file);
        json["dh"]![2]!.AsObject().Remove("d_mm");
        AssertSingleError(json, "$.dh[2].d_mm", "missing field");
    }

    [Fact]
    public void Missing_top_level_field_is_named()
    {
        var json = RobotFiles.Json("crb-1.0.json");
        json.AsObject().Remove("joints");
        var errors = Errors(json);
        Assert.Contains(errors, e => e.Path == "$.joints" && e.Message.Contains("missing field", StringComparison.Ordinal));
    }

    [Fact]
    public void Wrong_unit_is_named()
    {
        var json = RobotFiles.Json("crb-1.0.json");
        var row = json["dh"]![2]!.AsObject();
        var value = row["a_mm"]!.GetValue<double>();
        row.Remove("a_mm");
        row["a_cm"] = value / 10;
        var error = AssertSingleError(json, "$.dh[2].a_mm", "wrong unit");
        Assert.Contains("a_cm", error.Message, StringComparison.Ordinal);
        Assert.Contains("'mm'", error.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Wrong_unit_on_a_joint_range_is_named()
    {
        var json = RobotFiles.Json("lb-1.0.json");
        var joint = json["joints"]![3]!.AsObject();
        joint.Remove("max_deg");
        joint["max_rad"] = 2.618;
        AssertSingleError(json, "$.joints[3].max_deg", "wrong unit");
    }

    [Theory]
    [InlineData("NaN", "NaN")]
    [InlineData("Infinity", "finite")]
    [InlineData("68.58", "must be a number")]
    [InlineData("long", "must be a number")]
    public void Not_a_number_is_named(string text, string problem)
    {
        var json = RobotFiles.Json("crb-1.0.json");
        json["dh"]![2]!["a_mm"] = text;
        AssertSingleError(json, "$.dh[2].a_mm", problem);
    }

    [Fact]
    public void Boolean_or_null_where_a_number_belongs_is_named()
    {
        var json = RobotFiles.Json("crb-1.0.json");
        json["joints"]![0]!["min_deg"] = true;
        json["shoulder_cross_section_cm2"] = null;
        var errors = Errors(json);
        Assert.Contains(errors, e => e.Path == "$.joints[0].min_deg" && e.Message.Contains("must be a number", StringComparison.Ordinal));
        Assert.Contains(errors, e => e.Path == "$.shoulder_cross_section_cm2" && e.Message.Contains("null", StringComparison.Ordinal));
    }

    [Fact]
    public void A_bare_NaN_literal_is_invalid_JSON()
    {
        var text = File.ReadAllText(RobotFiles.Shipped("crb-1.0.json")).Replace("\"a_mm\": 68.58", "\"a_mm\": NaN", StringComparison.Ordinal);
        var path = _files.WriteText(text);
        var ex = Assert.Throws<RobotDataException>(() => RobotLoader.Load(path));
        var error = Assert.Single(ex.Errors);
        Assert.Equal(path, error.File);
        Assert.Equal("$", error.Path);
        Assert.Contains("not valid JSON", error.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Empty_DH_table_is_named()
    {
        var json = RobotFiles.Json("crb-1.0.json");
        json["dh"] = new JsonArray();
        var errors = Errors(json);
        Assert.Contains(errors, e => e.Path == "$.dh" && e.Message.Contains("empty", StringComparison.Ordinal));
    }

    [Fact]
    public void Joint_range_with_min_above_max_is_named()
    {
        var json = RobotFiles.Json("crb-1.0.json");
        json["joints"]![1]!["min_deg"] = 50;
        var error = AssertSingleError(json, "$.joints[1].min_deg", "min_deg 50 > max_deg 45");
        Assert.Contains("joint range", error.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Reference_to_a_motor_that_does_not_exist_is_named()
    {
        var json = RobotFiles.Json("lb-1.0.json");
        json["actuators"]![3]!["drivetrain"]!["motor"] = "0620 K 024 B";
        var error = AssertSingleError(json, "$.actuators[3].drivetrain.motor", "no component catalogue defines");
        Assert.Contains("0620 K 024 B", error.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Motor_reference_is_checked_even_without_a_motor_catalogue()
    {
        var json = RobotFiles.Json("crb-1.0.json");
        json["component_catalogs"] = new JsonArray("../components/gearheads.json");
        var errors = Errors(json);
        Assert.Contains(errors, e => e.Path == "$.actuators[0].drivetrain.motor" && e.Message.Contains("1226 S 012 B", StringComparison.Ordinal));
    }

    [Fact]
    public void Unknown_joint_in_the_DH_table_is_named()
    {
        var json = RobotFiles.Json("crb-1.0.json");
        json["dh"]![3]!["joint"] = "wrist";
        var errors = Errors(json);
        Assert.Contains(errors, e => e.Path == "$.dh[3].joint" && e.Message.Contains("\"wrist\"", StringComparison.Ordinal) && e.Message.Contains("does not define", StringComparison.Ordinal));
    }

    [Fact]
    public void Unknown_gearhead_series_and_coupling_joint_are_named()
    {
        var json = RobotFiles.Json("crb-1.0.json");
        json["actuators"]![2]!["drivetrain"]!["gearhead_series"] = "08/1";
        json["actuators"]![1]!["coupling"]!["shoulder_roll"] = 1;
        var errors = Errors(json);
        Assert.Contains(errors, e => e.Path == "$.actuators[2].drivetrain.gearhead_series");
        Assert.Contains(errors, e => e.Path == "$.actuators[1].coupling.shoulder_roll");
    }

    [Fact]
    public void Singular_coupling_is_refused()
    {
        var json = RobotFiles.Json("crb-1.0.json");
        json["actuators"]![1]!["coupling"] = new JsonObject { ["shoulder_yaw"] = 2, ["shoulder_pitch"] = 2 };
        AssertSingleError(json, "$.actuators", "singular");
    }

    [Fact]
    public void Two_actuators_on_one_joint_are_refused()
    {
        var json = RobotFiles.Json("crb-1.0.json");
        json["actuators"]![1]!["joint"] = "shoulder_yaw";
        var errors = Errors(json);
        Assert.Contains(errors, e => e.Path == "$.actuators[1].joint" && e.Message.Contains("already listed", StringComparison.Ordinal));
    }

    [Fact]
    public void Unknown_field_is_named()
    {
        var json = RobotFiles.Json("crb-1.0.json");
        json["joints"]![0]!["colour"] = "red";
        AssertSingleError(json, "$.joints[0].colour", "unknown field");
    }

    [Fact]
    public void Invalid_JSON_names_the_file()
    {
        var path = _files.WriteText("{ \"schema\": \"robotcontrol/robot/1\", \"name\": ");
        var ex = Assert.Throws<RobotDataException>(() => RobotLoader.Load(path));
        var error = Assert.Single(ex.Errors);
        Assert.Equal(path, error.File);
        Assert.Equal("$", error.Path);
        Assert.Contains("not valid JSON", error.Message, StringComparison.Ordinal);
        Assert.StartsWith(path + ": $: not valid JSON", ex.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Missing_file_names_the_file()
    {
        var path = Path.Combine(_files.Root, "robots", "absent.json");
        var ex = Assert.Throws<RobotDataException>(() => RobotLoader.Load(path));
        Assert.Equal(path, Assert.Single(ex.Errors).File);
    }

    [Fact]
    public void Problems_in_a_catalogue_name_the_catalogue()
    {
        var motors = JsonNode.Parse(File.ReadAllText(_files.Catalogue("motors.json")))!;
        motors["motors"]![1]!["stall_torque_mNm"] = "NaN";
        File.WriteAllText(_files.Catalogue("motors.json"), motors.ToJsonString());
        var path = _files.Write(RobotFiles.Json("crb-1.0.json"));
        var ex = Assert.Throws<RobotDataException>(() => RobotLoader.Load(path));
        var error = Assert.Single(ex.Errors);
        Assert.Equal(_files.Catalogue("motors.json"), error.File);
        Assert.Equal("$.motors[1].stall_torque_mNm", error.Path);
    }

    [Fact]
    public void Every_problem_is_reported_at_once()
    {
        var json = RobotFiles.Json("crb-1.0.json");
        json["dh"]![2]!["a_mm"] = "NaN";
        json["joints"]![2]!["min_deg"] = 120;
        json["actuators"]![0]!["drivetrain"]!["motor"] = "none";
        var ex = Assert.Throws<RobotDataException>(() => RobotLoader.Load(_files.Write(json)));
        Assert.Equal(["$.actuators[0].drivetrain.motor", "$.dh[2].a_mm", "$.joints[2].min_deg"], ex.Errors.Select(e => e.Path).Order());
        Assert.Contains("3 problems", ex.Message, StringComparison.Ordinal);
    }

    private IReadOnlyList<JsonProblem> Errors(JsonNode json)
    {
        var path = _files.Write(json);
        var ex = Assert.Throws<RobotDataException>(() => RobotLoader.Load(path));
        Assert.NotEmpty(ex.Errors);
        Assert.All(ex.Errors, e => Assert.Equal(path, e.File));
        Assert.All(ex.Errors, e => Assert.Contains($"{e.File}: {e.Path}: {e.Message}", ex.Message, StringComparison.Ordinal));
        return ex.Errors;
    }

    private JsonProblem AssertSingleError(JsonNode json, string jsonPath, string problem)
    {
        var errors = Errors(json);
        var error = Assert.Single(errors);
        Assert.Equal(jsonPath, error.Path);
        Assert.Contains(problem, error.Message, StringComparison.Ordinal);
        return error;
    }
}
