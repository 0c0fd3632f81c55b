using RobotControl.Hardware.Loading;
using RobotControl.Hardware.Model;

namespace RobotControl.Analysis.Tests;

/// <summary>The repository's robot files, loaded once.</summary>
internal static class TestRobots
{
    private static readonly Lazy<RobotDefinition> CrbRobot = new(() => RobotLoader.Load(PathOf("crb-1.0.json")));
    private static readonly Lazy<RobotDefinition> LbRobot = new(() => RobotLoader.Load(PathOf("lb-1.0.json")));

    public static RobotDefinition Crb => CrbRobot.Value;

    public static RobotDefinition Lb => LbRobot.Value;

    public static string PathOf(string file)
    {
        var dir = new DirectoryInfo(AppContext.BaseDirectory);
        while (dir is not null && !Directory.Exists(Path.Combine(dir.FullName, "hardware", "robots")))
        {
            dir = dir.Parent;
        }

        return Path.Combine(dir?.FullName ?? throw new InvalidOperationException("repository root not found"), "hardware", "robots", file);
    }
}
