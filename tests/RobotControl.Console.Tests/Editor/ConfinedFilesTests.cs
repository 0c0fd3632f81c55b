using System.Diagnostics;
using RobotControl.WebConsole.Editor;

namespace RobotControl.WebConsole.Tests.Editor;

/// <summary>The editor reads only regular files whose real path is inside its folders, never more than a bounded size, and never quotes them in a refusal.</summary>
[System.Runtime.Versioning.SupportedOSPlatform("linux")]
public sealed class ConfinedFilesTests : IDisposable
{
    private const string Secret = "SECRET-CONTENT-29";
    private readonly string _root = Directory.CreateTempSubdirectory("rc-confined").FullName;

    public ConfinedFilesTests()
    {
        Directory.CreateDirectory(Inside);
        Directory.CreateDirectory(Outside);
        File.WriteAllText(Path.Combine(Outside, "secret.json"), Secret);
        File.SetUnixFileMode(Path.Combine(Outside, "secret.json"), UnixFileMode.UserRead | UnixFileMode.UserWrite); // 0600
        File.WriteAllText(Path.Combine(Inside, "graph.json"), "{}");
    }

    private string Inside => Path.Combine(_root, "graphs");

    private string Outside => Path.Combine(_root, "elsewhere");

    public void Dispose() => Directory.Delete(_root, recursive: true);

    [Fact]
    public void A_regular_file_inside_is_read()
    {
        var files = new ConfinedFiles(Inside);
        Assert.Equal("{}", files.ReadText("graph", "graph.json", Path.Combine(Inside, "graph.json"), out var refusal));
        Assert.Equal(string.Empty, refusal);
        Assert.Null(files.Problem("path", "new.csv", Path.Combine(Inside, "new.csv"))); // not there yet: judged by its folder
    }

    [Theory]
    [InlineData("../elsewhere/secret.json")]
    [InlineData("/etc/passwd")]
    [InlineData("link.json")]
    [InlineData("linked-folder/secret.json")]
    public void A_path_leaving_the_folders_is_refused_without_quoting_the_file(string given)
    {
        File.CreateSymbolicLink(Path.Combine(Inside, "link.json"), Path.Combine(Outside, "secret.json"));
        Directory.CreateSymbolicLink(Path.Combine(Inside, "linked-folder"), Outside);
        var files = new ConfinedFiles(Inside);

        var text = files.ReadText("robot", given, Path.Combine(Inside, given), out var refusal);

        Assert.Null(text);
        Assert.Equal($"robot: '{given}' is outside the graphs folder and the robot folder (links that leave them are not followed)", refusal);
    }

    [Fact]
    public void A_fifo_is_refused_without_opening_it()
    {
        var fifo = Path.Combine(Inside, "recording.csv");
        using (var mkfifo = Process.Start("mkfifo", fifo))
        {
            mkfifo.WaitForExit();
            Assert.Equal(0, mkfifo.ExitCode);
        }

        var files = new ConfinedFiles(Inside);
        Assert.Null(files.ReadText("path", "recording.csv", fifo, out var refusal)); // opening it would wait for a writer forever
        Assert.Equal("path: 'recording.csv' is not a regular file (a FIFO, socket or device is never opened)", refusal);
    }

    [Fact]
    public void A_device_is_refused_and_a_folder_only_where_folders_are_asked_for()
    {
        var files = new ConfinedFiles(Inside, "/dev");
        Assert.Equal("path: '/dev/zero' is not a regular file (a FIFO, socket or device is never opened)", files.Problem("path", "/dev/zero", "/dev/zero"));
        Assert.Equal("path: 'graphs' is a folder, not a file", files.Problem("path", "graphs", Inside));
        Assert.Null(files.Problem("library", "graphs", Inside, folderToo: true));
    }

    [Fact]
    public void A_file_over_the_size_bound_is_not_read()
    {
        var big = Path.Combine(Inside, "big.json");
        using (var stream = File.Create(big))
        {
            stream.SetLength(ConfinedFiles.MaxBytes + 1);
        }

        Assert.Null(new ConfinedFiles(Inside).ReadText("graph", "big.json", big, out var refusal));
        Assert.Equal("graph: 'big.json' is larger than 4 MiB", refusal);
    }
}
