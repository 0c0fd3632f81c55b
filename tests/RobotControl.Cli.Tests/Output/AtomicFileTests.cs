using RobotControl.Cli.Output;

namespace RobotControl.Cli.Tests.Output;

public sealed class AtomicFileTests : IDisposable
{
    private readonly string _root = Path.Combine(Path.GetTempPath(), $"rc-atomic-{Guid.NewGuid():N}");

    public AtomicFileTests() => Directory.CreateDirectory(_root);

    [Fact]
    public void Replaces_the_file_whole_and_leaves_no_temporary_file()
    {
        var path = Path.Combine(_root, "report.json");
        File.WriteAllText(path, "old content that is longer than the new one");

        AtomicFile.WriteAllText(path, "{}");

        Assert.Equal("{}", File.ReadAllText(path));
        Assert.Equal([path], Directory.GetFileSystemEntries(_root));
    }

    [Fact]
    public void A_failed_write_leaves_the_old_file_and_no_temporary_file()
    {
        var path = Path.Combine(_root, "report.json");
        File.WriteAllText(path, "old");
        Directory.CreateDirectory(Path.Combine(_root, "sub"));

        Assert.ThrowsAny<IOException>(() => AtomicFile.WriteAllText(Path.Combine(_root, "missing", "x.json"), "{}"));

        Assert.Equal("old", File.ReadAllText(path));
        Assert.Equal(2, Directory.GetFileSystemEntries(_root).Length);
    }

    [Theory]
    [InlineData("/dev/full", "not a regular file")]
    [InlineData("/proc/x.json", "cannot write in /proc")]
    public void The_check_refuses_places_a_file_cannot_be_written(string path, string expected) =>
        Assert.Contains(expected, OutputPath.CheckFile(path), StringComparison.Ordinal);

    public void Dispose() => Directory.Delete(_root, recursive: true);
}
