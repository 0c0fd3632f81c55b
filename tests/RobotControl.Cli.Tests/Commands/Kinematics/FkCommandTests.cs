using System.CommandLine;
using RobotControl.Cli.Commands.Kinematics;

namespace RobotControl.Cli.Tests.Commands.Kinematics;

public sealed class FkCommandTests
{
    internal static string RobotFile(string name)
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            var candidate = Path.Combine(dir.FullName, "hardware", "robots", name);
            if (File.Exists(candidate))
            {
                return candidate;
            }
        }

        throw new InvalidOperationException("hardware/robots not found");
    }

    [Fact]
    public void Prints_pose_Jacobian_manipulability_and_the_closed_form_check_for_CRB()
    {
        var output = new StringWriter();
        var error = new StringWriter();
        var code = FkCommand.Run(RobotFile("crb-1.0.json"), "0,-90,0,0", output, error);
        Assert.Equal(0, code);
        Assert.Equal(string.Empty, error.ToString());
        var text = output.ToString();
        Assert.Contains("CRB-1.0", text, StringComparison.Ordinal);
        Assert.Contains("tool position (mm): 0.0000, 0.0000, -164.9730", text, StringComparison.Ordinal); // straight down, L1 + L2
        Assert.Contains("geometric Jacobian", text, StringComparison.Ordinal);
        Assert.Contains("manipulability", text, StringComparison.Ordinal);
        Assert.Contains("closed-form position IK", text, StringComparison.Ordinal);
    }

    [Fact]
    public void Runs_through_the_command_line_parser_for_LB()
    {
        var command = new FkCommand().Build();
        var root = new RootCommand { command };
        var output = new StringWriter();
        var result = root.Parse(["fk", RobotFile("lb-1.0.json"), "--joints-deg", "0,0,0,90,0"]);
        var code = result.Invoke(new InvocationConfiguration { Output = output, Error = new StringWriter() });
        Assert.Equal(0, code);
        Assert.Contains("tool position (mm): 87.5700, 86.5900, 0.0000", output.ToString(), StringComparison.Ordinal);
        Assert.DoesNotContain("closed-form", output.ToString(), StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("0,0,0", "3 values given")]
    [InlineData("0,0,NaN,0", "not a finite number")]
    [InlineData("0,0,x,0", "not a finite number")]
    public void Rejects_a_bad_joint_vector(string joints, string problem)
    {
        var error = new StringWriter();
        Assert.Equal(2, FkCommand.Run(RobotFile("crb-1.0.json"), joints, new StringWriter(), error));
        Assert.Contains(problem, error.ToString(), StringComparison.Ordinal);
    }

    [Fact]
    public void Reports_an_invalid_robot_file_with_its_path()
    {
        var path = Path.Combine(Path.GetTempPath(), $"robotctl-fk-{Guid.NewGuid():N}.json");
        File.WriteAllText(path, "{");
        try
        {
            var error = new StringWriter();
            Assert.Equal(2, FkCommand.Run(path, null, new StringWriter(), error));
            Assert.Contains(path, error.ToString(), StringComparison.Ordinal);
        }
        finally
        {
            File.Delete(path);
        }
    }
}
