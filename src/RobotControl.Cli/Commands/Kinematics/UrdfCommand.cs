using System.CommandLine;
using RobotControl.Kinematics.Urdf;

namespace RobotControl.Cli.Commands.Kinematics;

/// <summary>
/// <c>robotctl urdf &lt;robot file&gt; [--out file]</c>: writes the robot as URDF (both arms, joints named
/// <c>{arm}_{joint}</c>) for CoppeliaSim's URDF importer, RViz and the console's 3D view; standard output without --out.
/// </summary>
internal sealed class UrdfCommand : ICliCommand
{
    /// <inheritdoc />
    public Command Build()
    {
        var robotArgument = new Argument<FileInfo>("robot") { Description = "Robot data file, e.g. hardware/robots/lb-1.0.json" };
        var outOption = new Option<FileInfo?>("--out") { Description = "Where to write the URDF (default: standard output)" };
        var command = new Command("urdf", "Writes the robot (both arms) as URDF from its data file.");
        command.Arguments.Add(robotArgument);
        command.Options.Add(outOption);
        command.SetAction(parse => Run(
            parse.GetValue(robotArgument)!.FullName,
            parse.GetValue(outOption)?.FullName,
            parse.InvocationConfiguration.Output,
            parse.InvocationConfiguration.Error));
        return command;
    }

    /// <summary>Runs the command; returns the exit code (0 ok, 2 bad input or unwritable output).</summary>
    internal static int Run(string robotPath, string? outPath, TextWriter output, TextWriter error)
    {
        if (RobotFiles.LoadOrReport(robotPath, error) is not { } robot)
        {
            return 2;
        }

        if (outPath is null)
        {
            UrdfExport.Write(robot, output);
            return 0;
        }

        var text = new StringWriter();
        UrdfExport.Write(robot, text);
        try
        {
            File.WriteAllText(outPath, text.ToString());
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            error.WriteLine($"--out {outPath}: {ex.Message}");
            return 2;
        }

        output.WriteLine($"{robot.Name}: URDF written to {outPath}");
        return 0;
    }
}
