using RobotControl.Definitions.Model;
using RobotControl.TestSupport;

namespace RobotControl.Runtime.Tests.Support;

/// <summary>Short names for the shared fixtures (<see cref="RepositoryPaths"/>, <see cref="ShippedRobots"/>).</summary>
internal static class Repo
{
    public static string Root => RepositoryPaths.Root;

    public static string Path(string relative) => RepositoryPaths.Of(relative);

    public static RobotDefinition Lb => ShippedRobots.Lb;

    public static RobotDefinition Crb => ShippedRobots.Crb;
}
