using RobotControl.Plugins.Touch.Simulation;

namespace RobotControl.Plugins.Touch.Tests.Simulation;

public sealed class HandScriptTests
{
    private const string Header = "time_s,x_mm,y_mm,z_mm";

    private static string Fails(params string[] lines) =>
        Assert.Throws<FormatException>(() => HandScript.Parse(lines, "s.csv")).Message;

    private static (double[] Pose, double[] Velocity, bool Button1, bool Button2) At(HandScript script, double t)
    {
        var pose = new double[6];
        var velocity = new double[3];
        var hint = 0;
        script.Sample(t, pose, velocity, out var button1, out var button2, ref hint);
        return (pose, velocity, button1, button2);
    }

    [Theory]
    [InlineData("button2,yaw_rad,pitch_rad,roll_rad,z_mm,y_mm,x_mm,button1,time_s", "")] // a script
    [InlineData("p.button2,p.yaw,p.pitch,p.roll,p.z,p.y,p.x,p.button1,time_s", "p.")] // a recording
    public void Every_column_is_read_by_its_name_in_any_order(string header, string prefix)
    {
        var script = HandScript.Parse([header, "1,0.3,0.2,0.1,3,2,1,1,0", "0,0,0,0,0,0,0,0,2"], "s.csv", prefix);

        var (pose, _, button1, button2) = At(script, 0);

        Assert.Equal([1.0, 2.0, 3.0, 0.1, 0.2, 0.3], pose);
        Assert.True(button1);
        Assert.True(button2);
        Assert.Equal(2.0, script.DurationSeconds);
    }

    [Fact]
    public void Orientation_and_buttons_are_optional()
    {
        var script = HandScript.Parse([Header, "0,1,2,3", "1,1,2,3"], "s.csv");

        var (pose, _, button1, button2) = At(script, 0.5);

        Assert.Equal([1.0, 2.0, 3.0, 0, 0, 0], pose);
        Assert.False(button1);
        Assert.False(button2);
    }

    [Fact]
    public void A_button_at_exactly_one_half_is_pressed()
    {
        var script = HandScript.Parse(
            [Header + ",button1,button2", "0,0,0,0,0.5,0.5", "1,0,0,0,0.49,0.49", "2,0,0,0,1,0"],
            "s.csv");

        var half = At(script, 0);
        var below = At(script, 1);
        var above = At(script, 2);

        Assert.True(half.Button1);
        Assert.True(half.Button2);
        Assert.False(below.Button1);
        Assert.False(below.Button2);
        Assert.True(above.Button1);
        Assert.False(above.Button2);
    }

    [Fact]
    public void Between_keyframes_the_pose_is_interpolated_and_the_velocity_is_the_segments_slope()
    {
        // x: 2 mm at 1 s, 10 mm at 3 s, 16 mm at 4 s. At 1.5 s: a quarter into the first segment, 2 + 8 / 4 = 4 mm,
        // moving at 8 mm / 2 s = 4 mm/s; the second segment moves at 6 mm/s.
        var script = HandScript.Parse([Header + ",yaw_rad", "1,2,0,0,0", "3,10,0,0,1", "4,16,0,0,1"], "s.csv");

        var (pose, velocity, _, _) = At(script, 1.5);

        Assert.Equal(4.0, pose[0], 12);
        Assert.Equal(0.25, pose[5], 12);
        Assert.Equal(4.0, velocity[0], 12);
        Assert.Equal(6.0, At(script, 3.5).Velocity[0], 12);
    }

    [Fact]
    public void The_hand_moves_from_its_first_keyframe_and_rests_from_its_last_one()
    {
        var script = HandScript.Parse([Header, "1,2,0,0", "3,10,0,0", "4,16,0,0"], "s.csv");

        var before = At(script, 0.5);
        var first = At(script, 1);
        var last = At(script, 4);
        var after = At(script, 5);

        Assert.Equal((2.0, 0.0), (before.Pose[0], before.Velocity[0]));
        Assert.Equal((2.0, 4.0), (first.Pose[0], first.Velocity[0]));
        Assert.Equal((16.0, 0.0), (last.Pose[0], last.Velocity[0]));
        Assert.Equal((16.0, 0.0), (after.Pose[0], after.Velocity[0]));
    }

    [Fact]
    public void A_header_without_the_position_columns_is_refused_naming_its_line()
    {
        Assert.Equal("s.csv:3: the header needs time_s, x_mm, y_mm, z_mm columns", Fails("# a comment", "", "time_s,x_mm,y_mm", "0,0,0"));
        Assert.Equal("s.csv:1: the header needs time_s, x_mm, y_mm, z_mm columns", Fails("t,x,y,z", "0,0,0,0"));
    }

    [Fact]
    public void A_recording_without_the_prefixed_columns_is_refused()
    {
        var e = Assert.Throws<FormatException>(() => HandScript.Parse(["time_s,x,y,z", "0,0,0,0", "1,0,0,0"], "rec.csv", "p."));

        Assert.Equal("rec.csv:1: the header needs time_s, p.x, p.y, p.z columns", e.Message);
    }

    [Fact]
    public void A_row_with_the_wrong_number_of_cells_is_refused()
    {
        Assert.Equal("s.csv:4: 3 cells, the header has 4", Fails(Header, "# keyframes", "0,0,0,0", "1,0,0"));
    }

    [Theory]
    [InlineData("abc", "x_mm")]
    [InlineData("NaN", "y_mm")]
    [InlineData("Infinity", "z_mm")]
    public void A_cell_that_is_not_a_finite_number_is_refused(string cell, string column)
    {
        var row = column switch
        {
            "x_mm" => $"0,{cell},0,0",
            "y_mm" => $"0,0,{cell},0",
            _ => $"0,0,0,{cell}",
        };

        Assert.Equal($"s.csv:3: '{cell}' in column {column} is not a finite number", Fails(Header, "", row, "1,0,0,0"));
    }

    [Fact]
    public void Time_that_does_not_increase_is_refused()
    {
        Assert.Equal("s.csv:4: time 1 s does not increase", Fails(Header, "0,0,0,0", "1,0,0,0", "1,5,0,0"));
        Assert.Equal("s.csv:3: time 0 s does not increase", Fails(Header, "1,0,0,0", "0,0,0,0"));
    }

    [Fact]
    public void A_script_needs_two_keyframes()
    {
        Assert.Equal("s.csv: a script needs at least two keyframes", Fails(Header, "0,0,0,0"));
        Assert.Equal("s.csv: a script needs at least two keyframes", Fails(Header));
    }

    [Fact]
    public void Null_arguments_are_refused_by_name()
    {
        Assert.Equal("lines", Assert.Throws<ArgumentNullException>(() => HandScript.Parse(null!, "s.csv")).ParamName);
        Assert.Equal("columnPrefix", Assert.Throws<ArgumentNullException>(() => HandScript.Parse([Header, "0,0,0,0", "1,0,0,0"], "s.csv", null!)).ParamName);
        Assert.Equal("path", Assert.Throws<ArgumentException>(() => HandScript.Load("")).ParamName);
        Assert.Equal("path", Assert.Throws<ArgumentNullException>(() => HandScript.Load(null!)).ParamName);
    }

    [Fact]
    public void A_script_file_is_loaded_and_its_errors_name_the_file()
    {
        var dir = Directory.CreateTempSubdirectory("handscript");
        try
        {
            var good = Path.Combine(dir.FullName, "hand.csv");
            var bad = Path.Combine(dir.FullName, "bad.csv");
            File.WriteAllLines(good, [Header, "0,1,0,0", "2,3,0,0"]);
            File.WriteAllLines(bad, [Header, "0,1,0,0"]);

            var script = HandScript.Load(good);

            Assert.Equal((2, 2.0), (script.Count, script.DurationSeconds));
            Assert.Equal(2.0, At(script, 1).Pose[0], 12);
            Assert.Equal($"{bad}: a script needs at least two keyframes", Assert.Throws<FormatException>(() => HandScript.Load(bad)).Message);
        }
        finally
        {
            dir.Delete(true);
        }
    }
}
