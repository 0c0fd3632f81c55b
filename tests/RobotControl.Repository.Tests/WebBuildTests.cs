using System.Diagnostics;
using System.Text.Json;
using System.Xml.Linq;
using RobotControl.TestSupport;

namespace RobotControl.Repository.Tests;

/// <summary>
/// Issue 29, class 10: a build that changes the tree. The console's front-end build (the Console project's
/// <c>InstallWeb</c> and <c>BuildWeb</c> targets) leaves a fresh clone clean: the committed package-lock.json lists
/// every platform's optional packages, so <c>npm ci</c> accepts it and nothing rewrites it.
/// </summary>
public sealed class WebBuildTests
{
    private const string Web = "src/RobotControl.Console/web";
    private const string Project = "src/RobotControl.Console/RobotControl.Console.csproj";

    [Fact]
    public void The_lock_file_lists_every_optional_package_its_packages_declare()
    {
        using var doc = JsonDocument.Parse(File.ReadAllText(RepositoryPaths.Of($"{Web}/package-lock.json")));
        var packages = doc.RootElement.GetProperty("packages");
        var entries = packages.EnumerateObject().Select(p => p.Name).ToHashSet(StringComparer.Ordinal);

        var declared = packages.EnumerateObject()
            .Where(p => p.Value.TryGetProperty("optionalDependencies", out _))
            .SelectMany(p => p.Value.GetProperty("optionalDependencies").EnumerateObject().Select(d => (Owner: p.Name, Name: d.Name)))
            .ToList();
        var missing = declared.Where(d => !entries.Contains($"{d.Owner}/node_modules/{d.Name}") && !entries.Contains($"node_modules/{d.Name}")).ToList();

        Assert.Contains(declared, d => d.Name == "@rollup/rollup-win32-x64-msvc"); // rollup's are there to be checked
        Assert.True(missing.Count == 0, $"package-lock.json lacks optional packages that `npm ci` needs (regenerate it: docs/dependencies.md): {string.Join(", ", missing.Select(m => $"{m.Name} (of {m.Owner})"))}");
    }

    [Fact]
    public void The_console_build_uses_npm_ci()
    {
        var install = Commands(RepositoryPaths.Root, "InstallWeb");

        Assert.Equal(["npm ci --no-audit --no-fund"], install);
    }

    /// <summary>Clones HEAD, runs the web build commands as the clone's csproj has them, and checks the clone is clean (about 25 s).</summary>
    [Fact]
    public void A_fresh_clone_is_clean_after_the_console_build()
    {
        var clone = Directory.CreateTempSubdirectory("rc-webbuild-").FullName;
        try
        {
            var head = Run("git", ["rev-parse", "HEAD"], RepositoryPaths.Root).Trim();
            Run("git", ["clone", "--quiet", "--no-checkout", RepositoryPaths.Root, clone], RepositoryPaths.Root);
            Run("git", ["checkout", "--quiet", head], clone);
            var web = Path.Combine(clone, Web);

            foreach (var command in Commands(clone, "InstallWeb").Concat(Commands(clone, "BuildWeb")))
            {
                Run("sh", ["-c", command], web);
            }

            Assert.True(File.Exists(Path.Combine(web, "dist", "index.html")), "the build produced no dist/index.html");
            var status = Run("git", ["status", "--porcelain", "--untracked-files=all"], clone);
            Assert.True(status.Length == 0, $"the console build changed a fresh clone:\n{status}");
        }
        finally
        {
            Directory.Delete(clone, recursive: true);
        }
    }

    /// <summary>The commands of <paramref name="target"/>'s <c>Exec</c> tasks in the Console project under <paramref name="root"/>, in order.</summary>
    private static string[] Commands(string root, string target)
    {
        var project = XDocument.Load(Path.Combine(root, Project));
        var t = project.Root!.Elements("Target").Single(e => (string?)e.Attribute("Name") == target);
        return [.. t.Elements("Exec").Select(e => (string)e.Attribute("Command")!)];
    }

    /// <summary>Runs <paramref name="file"/> in <paramref name="directory"/>; returns its output; fails the test with its output when it fails.</summary>
    private static string Run(string file, string[] arguments, string directory)
    {
        var start = new ProcessStartInfo(file)
        {
            WorkingDirectory = directory,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
        };
        foreach (var a in arguments)
        {
            start.ArgumentList.Add(a);
        }

        using var process = Process.Start(start) ?? throw new InvalidOperationException($"could not start {file}");
        var error = process.StandardError.ReadToEndAsync();
        var output = process.StandardOutput.ReadToEnd();
        if (!process.WaitForExit(TimeSpan.FromMinutes(5)))
        {
            process.Kill(entireProcessTree: true);
            Assert.Fail($"{file} {string.Join(' ', arguments)} took more than 5 minutes");
        }

        Assert.True(process.ExitCode == 0, $"{file} {string.Join(' ', arguments)} exited {process.ExitCode}:\n{output}\n{error.Result}");
        return output;
    }
}
