using RobotControl.Definitions.Model;
using RobotControl.TestSupport;

namespace RobotControl.Analysis.Tests;

/// <summary>The repository's robot files, loaded once (by <see cref="ShippedRobots"/>).</summary>
internal static class TestRobots
{
    public static RobotDefinition Crb => ShippedRobots.Crb;

    public static RobotDefinition Lb => ShippedRobots.Lb;

    public static string PathOf(string file) => RepositoryPaths.Robot(file);
}
