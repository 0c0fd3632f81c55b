namespace RobotControl.TestSupport;

/// <summary>The repository the tests run in: its root (the folder holding RobotControl.sln) and paths below it.</summary>
public static class RepositoryPaths
{
    /// <summary>The repository root.</summary>
    public static string Root { get; } = FindRoot();

    /// <summary>The full path of <paramref name="relative"/> (a path relative to the root, '/'-separated).</summary>
    public static string Of(string relative)
    {
        ArgumentNullException.ThrowIfNull(relative);
        return Path.Combine(Root, relative.Replace('/', Path.DirectorySeparatorChar));
    }

    /// <summary>The full path of a shipped robot file, e.g. <c>lb-1.0.json</c>.</summary>
    public static string Robot(string fileName) => Of("hardware/robots/" + fileName);

    /// <summary>The full path of a firmware file, e.g. <c>protocol/test-vectors.json</c>.</summary>
    public static string Firmware(string relative) => Of("firmware/" + relative);

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
