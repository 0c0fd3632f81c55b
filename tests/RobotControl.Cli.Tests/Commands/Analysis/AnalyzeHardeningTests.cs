namespace RobotControl.Cli.Tests.Commands.Analysis;

/// <summary><c>robotctl analyze</c> checks its output and bounds its work before it starts (issue 18, classes 4 and 5).</summary>
public sealed class AnalyzeHardeningTests : IDisposable
{
    private readonly string _root = Path.Combine(Path.GetTempPath(), $"rc-analyze-hard-{Guid.NewGuid():N}");

    public AnalyzeHardeningTests() => Directory.CreateDirectory(_root);

    private static string Robot => Cli.RepoFile("hardware/robots/lb-1.0.json");

    [Fact]
    public void An_existing_file_as_the_output_directory_is_refused_before_the_analysis()
    {
        var file = Path.Combine(_root, "taken");
        File.WriteAllText(file, "keep");

        var result = Cli.Run("analyze", Robot, "--out", file);

        Cli.AssertRefused(result, "--out: ");
        Assert.Contains("is a file, not a directory", result.Error, StringComparison.Ordinal);
        Assert.Equal("keep", File.ReadAllText(file));
    }

    [Fact]
    public void A_sweep_step_that_would_need_too_many_points_is_refused_with_the_estimate()
    {
        var (code, _, error) = Cli.Run("analyze", Robot, "--out", Path.Combine(_root, "out"), "--sweep", "shoulder_yaw:-90:45,elbow:0:105,step=0.0001");

        Assert.NotEqual(0, code);
        Assert.Contains("grid points (limit", error, StringComparison.Ordinal);
        Assert.Contains("use a step of at least", error, StringComparison.Ordinal);
        Assert.False(Directory.Exists(Path.Combine(_root, "out")));
    }

    [Fact]
    public void A_voxel_size_that_would_need_too_many_cells_is_refused_with_the_estimate()
    {
        var (code, _, error) = Cli.Run("analyze", Robot, "--out", Path.Combine(_root, "out"), "--voxel-mm", "0.02");

        Assert.NotEqual(0, code);
        Assert.Contains("--voxel-mm 0.02: the workspace grid would have", error, StringComparison.Ordinal);
        Assert.False(Directory.Exists(Path.Combine(_root, "out")));
    }

    public void Dispose() => Directory.Delete(_root, recursive: true);
}
