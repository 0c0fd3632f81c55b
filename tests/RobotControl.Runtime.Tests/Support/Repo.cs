using RobotControl.Hardware.Loading;
using RobotControl.Hardware.Model;

namespace RobotControl.Runtime.Tests.Support;

internal static class Repo
{
    public static string Root { get; } = FindRoot();

    public static string Path(string relative) => System.IO.Path.Combine(Root, relative);

    public static RobotDefinition Lb { get; } = RobotLoader.Load(Path("hardware/robots/lb-1.0.json"));

    public static RobotDefinition Crb { get; } = RobotLoader.Load(Path("hardware/robots/crb-1.0.json"));

    private static string FindRoot()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            if (File.Exists(System.IO.Path.Combine(dir.FullName, "RobotControl.sln")))
            {
                return dir.FullName;
            }
        }

        throw new InvalidOperationException("repository root not found");
    }
}
