using System.Diagnostics;
using RobotControl.TestSupport;

namespace RobotControl.Repository.Tests;

/// <summary>The repository's tracked files (<c>git ls-files</c>), read as text where they are text.</summary>
internal static class TrackedFiles
{
    private static readonly Lazy<IReadOnlyList<string>> PathsLazy = new(ListTracked);

    /// <summary>Every tracked file, '/'-separated and relative to the root, that still exists in the work tree.</summary>
    public static IReadOnlyList<string> Paths => PathsLazy.Value;

    /// <summary>The first path segment of every tracked file: the repository's top-level folders and files.</summary>
    public static IReadOnlySet<string> TopLevelEntries { get; } = Paths.Select(p => p.Split('/')[0]).ToHashSet(StringComparer.Ordinal);

    /// <summary>Tracked text files (no NUL byte) with their contents.</summary>
    public static IEnumerable<(string Path, string Text)> Text()
    {
        foreach (var path in Paths)
        {
            var bytes = File.ReadAllBytes(RepositoryPaths.Of(path));
            if (Array.IndexOf(bytes, (byte)0) < 0)
            {
                yield return (path, System.Text.Encoding.UTF8.GetString(bytes));
            }
        }
    }

    private static List<string> ListTracked()
    {
        var start = new ProcessStartInfo("git", "ls-files -z")
        {
            WorkingDirectory = RepositoryPaths.Root,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
        };
        using var git = Process.Start(start) ?? throw new InvalidOperationException("could not start git");
        var output = git.StandardOutput.ReadToEnd();
        git.WaitForExit();
        if (git.ExitCode != 0)
        {
            throw new InvalidOperationException("git ls-files failed: " + git.StandardError.ReadToEnd());
        }

        return output.Split('\0', StringSplitOptions.RemoveEmptyEntries)
            .Where(p => File.Exists(RepositoryPaths.Of(p)))
            .ToList();
    }
}
