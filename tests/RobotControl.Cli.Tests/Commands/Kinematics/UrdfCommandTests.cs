using System.Xml.Linq;
using RobotControl.Cli.Commands.Kinematics;

namespace RobotControl.Cli.Tests.Commands.Kinematics;

public sealed class UrdfCommandTests
{
    [Fact]
    public void Writes_both_arms_of_the_robot_to_the_out_file()
    {
        var path = Path.Combine(Path.GetTempPath(), $"urdf-{Guid.NewGuid():N}.urdf");
        var output = new StringWriter();
        try
        {
            Assert.Equal(0, UrdfCommand.Run(FkCommandTests.RobotFile("lb-1.0.json"), path, output, new StringWriter()));
            var robot = XDocument.Load(path).Root!;
            Assert.Equal("LB-1.0", (string?)robot.Attribute("name"));
            Assert.Equal(10, robot.Elements("joint").Count(j => (string?)j.Attribute("type") == "revolute"));
            Assert.Contains(robot.Elements("joint"), j => (string?)j.Attribute("name") == "left_tool_roll");
            Assert.Equal($"LB-1.0: URDF written to {path}\n", output.ToString().ReplaceLineEndings("\n"));
        }
        finally
        {
            File.Delete(path);
        }
    }

    [Fact]
    public void Without_out_the_urdf_goes_to_standard_output()
    {
        var output = new StringWriter();
        Assert.Equal(0, UrdfCommand.Run(FkCommandTests.RobotFile("crb-1.0.json"), null, output, new StringWriter()));
        Assert.Equal("CRB-1.0", (string?)XDocument.Parse(output.ToString()).Root!.Attribute("name"));
    }

    [Fact]
    public void A_bad_robot_file_or_out_path_is_one_line_and_exit_code_2()
    {
        var error = new StringWriter();
        Assert.Equal(2, UrdfCommand.Run("/nonexistent/robot.json", null, new StringWriter(), error));
        Assert.Single(error.ToString().Trim().Split('\n'));

        error = new StringWriter();
        Assert.Equal(2, UrdfCommand.Run(FkCommandTests.RobotFile("lb-1.0.json"), "/nonexistent-dir/x.urdf", new StringWriter(), error));
        Assert.StartsWith("--out /nonexistent-dir/x.urdf: ", error.ToString(), StringComparison.Ordinal);
    }
}
