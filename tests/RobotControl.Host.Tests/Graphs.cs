namespace RobotControl.Host.Tests;

/// <summary>The repository's graph files.</summary>
internal static class Graphs
{
    public static string Path(string name)
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            var path = System.IO.Path.Combine(dir.FullName, "graphs", name);
            if (File.Exists(path))
            {
                return path;
            }
        }

        throw new FileNotFoundException($"graphs/{name} not found above {AppContext.BaseDirectory}");
    }
}
