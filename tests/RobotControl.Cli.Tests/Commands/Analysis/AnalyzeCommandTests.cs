using System.CommandLine;
using RobotControl.Cli.Commands.Analysis;

namespace RobotControl.Cli.Tests.Commands.Analysis;

public sealed class AnalyzeCommandTests : IDisposable
{
    private readonly string _root = Path.Combine(Path.GetTempPath(), $"rc-analyze-cli-{Guid.NewGuid():N}");

    public AnalyzeCommandTests() => Directory.CreateDirectory(_root);

    [Fact]
    public void Analyzes_a_robot_file_into_the_output_directory()
    {
        var outDir = Path.Combine(_root, "out");

        var (code, output, error) = Invoke("analyze", RobotFile("crb-1.0.json"), "--out", outDir, "--no-workspace",
            "--sweep", "shoulder_yaw:-90:45,elbow:0:105,step=5,fixed=shoulder_pitch:0");

        Assert.True(code == 0, error);
        Assert.Contains("CRB-1.0: 616 sweep points", output, StringComparison.Ordinal);
        Assert.True(File.Exists(Path.Combine(outDir, "summary.json")));
        Assert.Equal(617, File.ReadAllLines(Path.Combine(outDir, "sweep.csv")).Length);
        Assert.True(File.Exists(Path.Combine(outDir, "fz.png")));
    }

    [Fact]
    public void A_bad_robot_file_gives_a_clear_error_and_writes_nothing()
    {
        var text = File.ReadAllText(RobotFile("lb-1.0.json"))
            .Replace("\"gearhead_ratio\": 1024", "\"gearhead_ratio\": \"many\"", StringComparison.Ordinal)
            .Replace("../components/", Path.GetDirectoryName(RobotFile("lb-1.0.json")) + "/../components/", StringComparison.Ordinal);
        var bad = Path.Combine(_root, "bad.json");
        File.WriteAllText(bad, text);
        var outDir = Path.Combine(_root, "never");

        var (code, _, error) = Invoke("analyze", bad, "--out", outDir);

        Assert.NotEqual(0, code);
        Assert.Contains("gearhead_ratio", error, StringComparison.Ordinal);
        Assert.Contains("must be a number", error, StringComparison.Ordinal);
        Assert.False(Directory.Exists(outDir));
        Assert.Equal([bad], Directory.GetFileSystemEntries(_root));
    }

    [Fact]
    public void A_bad_sweep_names_the_problem_and_writes_nothing()
    {
        var outDir = Path.Combine(_root, "never");

        var (code, _, error) = Invoke("analyze", RobotFile("lb-1.0.json"), "--out", outDir, "--sweep", "shoulder_yaw:-90:45,wrist:0:10");

        Assert.NotEqual(0, code);
        Assert.Contains("unknown joint 'wrist'", error, StringComparison.Ordinal);
        Assert.False(Directory.Exists(outDir));
    }

    [Fact]
    public void Help_describes_the_options()
    {
        var (code, output, _) = Invoke("analyze", "--help");

        Assert.Equal(0, code);
        Assert.Contains("--coupling-aware", output, StringComparison.Ordinal);
        Assert.Contains("--sweep", output, StringComparison.Ordinal);
    }

    public void Dispose() => Directory.Delete(_root, recursive: true);

    private static (int Code, string Output, string Error) Invoke(params string[] args)
    {
        var root = new RootCommand { new AnalyzeCommand().Build() };
        var output = new StringWriter();
        var error = new StringWriter();
        var code = root.Parse(args).Invoke(new InvocationConfiguration { Output = output, Error = error });
        return (code, output.ToString(), error.ToString());
    }

    private static string RobotFile(string name)
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            var candidate = Path.Combine(dir.FullName, "hardware", "robots", name);
            if (File.Exists(candidate))
            {
                return candidate;
            }
        }

        throw new InvalidOperationException("hardware/robots not found");
    }
}
