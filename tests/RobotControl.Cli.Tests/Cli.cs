using System.Text.Json.Nodes;

namespace RobotControl.Cli.Tests;

/// <summary>Runs <c>robotctl</c> in-process through its real entry path and finds the repository's files.</summary>
internal static class Cli
{
    /// <summary>Invokes robotctl with <paramref name="args"/>; returns the exit code and both streams.</summary>
    public static (int Code, string Output, string Error) Run(params string[] args)
    {
        var output = new StringWriter();
        var error = new StringWriter();
        var code = CliApp.Invoke(args, output, error);
        return (code, output.ToString(), error.ToString());
    }

    /// <summary>A path inside the repository, e.g. <c>hardware/robots/lb-1.0.json</c>.</summary>
    public static string RepoFile(string relative)
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            var candidate = Path.Combine(dir.FullName, relative);
            if (File.Exists(candidate) && Directory.Exists(Path.Combine(dir.FullName, "hardware")))
            {
                return candidate;
            }
        }

        throw new InvalidOperationException($"{relative} not found above {AppContext.BaseDirectory}");
    }

    /// <summary>Writes a changed copy of LB-1.0's robot file into <paramref name="directory"/> (catalogue paths kept); returns its path.</summary>
    public static string CopyRobot(string directory, Action<JsonObject> change)
    {
        var source = RepoFile("hardware/robots/lb-1.0.json");
        var text = File.ReadAllText(source).Replace("../components/", Path.GetDirectoryName(source) + "/../components/", StringComparison.Ordinal);
        var json = JsonNode.Parse(text)!.AsObject();
        change(json);
        var path = Path.Combine(directory, "robot.json");
        File.WriteAllText(path, json.ToJsonString());
        return path;
    }

    /// <summary>Asserts a refusal: non-zero exit, one line on the error stream containing <paramref name="expected"/>, no stack trace.</summary>
    public static void AssertRefused((int Code, string Output, string Error) result, string expected)
    {
        Assert.True(result.Code != 0, $"exit 0; output: {result.Output}");
        var lines = result.Error.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);
        Assert.True(lines.Length == 1, $"expected one error line, got: {result.Error}");
        Assert.Contains(expected, lines[0], StringComparison.Ordinal);
        Assert.DoesNotContain("   at ", result.Error, StringComparison.Ordinal);
        Assert.DoesNotContain("Exception", result.Error, StringComparison.Ordinal);
    }
}
