namespace RobotControl.Bus.Tests.Support;

/// <summary>Files of the repository the tests read (firmware vectors, robot files).</summary>
internal static class RepoPaths
{
    public static string Root { get; } = FindRoot();

    public static string Robot(string name) => Path.Combine(Root, "hardware", "robots", name);

    public static string Firmware(string relative) => Path.Combine(Root, "firmware", relative);

    private static string FindRoot()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            if (File.Exists(Path.Combine(dir.FullName, "RobotControl.sln")))
            {
                return dir.FullName;
            }
        }

        throw new DirectoryNotFoundException("repository root (RobotControl.sln) not found above " + AppContext.BaseDirectory);
    }
}
