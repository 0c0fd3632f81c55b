using RobotControl.Definitions.Loading;
using RobotControl.Definitions.Model;

namespace RobotControl.Cli.Commands;

/// <summary>Loading the robot file a command is given.</summary>
internal static class RobotFiles
{
    /// <summary>The robot in <paramref name="path"/>, or null after writing the loader's one-line message to <paramref name="error"/>.</summary>
    public static RobotDefinition? LoadOrReport(string path, TextWriter error)
    {
        try
        {
            return RobotLoader.Load(path);
        }
        catch (RobotDataException ex)
        {
            error.WriteLine(ex.Message);
            return null;
        }
    }
}
