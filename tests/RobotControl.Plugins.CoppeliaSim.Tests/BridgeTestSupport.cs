using RobotControl.Definitions.Loading;
using RobotControl.Definitions.Model;
using RobotControl.Plugins.CoppeliaSim;
using RobotControl.Plugins.Standard.Conditioning;
using RobotControl.Plugins.Touch;
using RobotControl.Runtime.Discovery;

namespace RobotControl.Plugins.CoppeliaSim.Tests;

/// <summary>The repository, the LB-1.0 robot, the host's plug-in catalogue and the default scene paths of its joints.</summary>
internal static class BridgeTestSupport
{
    public static string Root { get; } = FindRoot();

    public static RobotDefinition Lb { get; } = RobotLoader.Load(Path.Combine(Root, "hardware/robots/lb-1.0.json"));

    public static PluginCatalog Catalog() =>
        PluginCatalog.FromAssemblies(typeof(ClutchPlugin).Assembly, typeof(TouchPlugin).Assembly, typeof(CoppeliaSimPlugin).Assembly);

    /// <summary>Signal (<c>right.elbow</c>) and default scene path (<c>/LB1/right_elbow</c>) of every joint, arm-major.</summary>
    public static IReadOnlyList<(string Signal, string Path)> Joints { get; } =
        [.. Lb.Arms.SelectMany(a => Lb.Joints.Select(j => ($"{a.Name}.{j.Name}", $"/LB1/{a.Name}_{j.Name}")))];

    public static void WaitFor(Func<bool> condition, TimeSpan timeout, string what)
    {
        var end = DateTime.UtcNow + timeout;
        while (!condition())
        {
            if (DateTime.UtcNow > end)
            {
                Assert.Fail($"timed out waiting for {what}");
            }

            Thread.Sleep(5);
        }
    }

    private static string FindRoot()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            if (File.Exists(Path.Combine(dir.FullName, "RobotControl.sln")))
            {
                return dir.FullName;
            }
        }

        throw new InvalidOperationException("repository root not found");
    }
}
