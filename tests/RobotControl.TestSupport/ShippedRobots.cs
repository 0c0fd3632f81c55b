using RobotControl.Definitions.Loading;
using RobotControl.Definitions.Model;

namespace RobotControl.TestSupport;

/// <summary>The robots shipped in <c>hardware/robots/</c>, each loaded once per test run.</summary>
public static class ShippedRobots
{
    private static readonly Lazy<RobotDefinition> LbLazy = new(() => RobotLoader.Load(RepositoryPaths.Robot("lb-1.0.json")));
    private static readonly Lazy<RobotDefinition> CrbLazy = new(() => RobotLoader.Load(RepositoryPaths.Robot("crb-1.0.json")));

    /// <summary>LB-1.0 (5-DOF arms).</summary>
    public static RobotDefinition Lb => LbLazy.Value;

    /// <summary>CRB-1.0 (4-DOF arms).</summary>
    public static RobotDefinition Crb => CrbLazy.Value;

    /// <summary>The shipped robot whose file is named <paramref name="fileName"/> (<c>lb-1.0.json</c> or <c>crb-1.0.json</c>).</summary>
    public static RobotDefinition ByFileName(string fileName) => fileName switch
    {
        "lb-1.0.json" => Lb,
        "crb-1.0.json" => Crb,
        _ => throw new ArgumentException($"no shipped robot file named {fileName}", nameof(fileName)),
    };
}
