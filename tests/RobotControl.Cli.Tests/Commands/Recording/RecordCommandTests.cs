using RobotControl.Cli.Tests.Commands.Run;
using RobotControl.Host.Recording.Mcap;
using RobotControl.TestSupport.Mcap;

namespace RobotControl.Cli.Tests.Commands.Recording;

/// <summary>
/// <c>robotctl run --record</c> and <c>robotctl export</c>: a recording cut short by a kill is readable up to its last
/// complete chunk, and bad input gets one line naming the file or option, with nothing overwritten without --force.
/// </summary>
[Collection(RunProcess.Collection)]
public sealed class RecordCommandTests
{
    [Fact]
    public void A_run_killed_mid_recording_leaves_a_file_read_up_to_its_last_complete_chunk_and_exported_with_one_line()
    {
        var dir = Directory.CreateTempSubdirectory("rc-rec-").FullName;
        var file = Path.Combine(dir, "killed.mcap");
        using (var run = new RunProcess("run", RunProcess.Graph, "--virtual", "--duration", "10m", "--record", file))
        {
            run.WaitFor("t=", RunProcess.Patience);
            var waited = System.Diagnostics.Stopwatch.StartNew();
            while (new FileInfo(file).Length < (2 << 20) && waited.Elapsed < RunProcess.Patience)
            {
                Thread.Sleep(100); // a few chunks on disk
            }

            run.Signal("KILL");
            run.WaitForExit(RunProcess.Patience);
        }

        var check = McapCheck.Read(file);
        using var own = McapFile.Open(file);

        Assert.Null(check.Error);
        Assert.False(check.Complete);
        Assert.True(check.StreamCounts["/arms/right/joints"] > 100, $"{check.StreamCounts["/arms/right/joints"]} joint messages");
        Assert.Equal(check.StreamCounts.Values.Sum(), own.Messages().LongCount());
        Assert.Equal(check.StreamCounts.Values.Sum(), (long)own.MessageCount); // the scan's count
        var csv = Path.Combine(dir, "csv");
        var (code, output, error) = Cli.Run("export", file, "--csv", csv, "--topics", "/arms/right/joints");
        Assert.Equal(0, code);
        Assert.Equal(own.Truncated + Environment.NewLine, error);
        Assert.Contains($"killed.mcap: {check.StreamCounts["/arms/right/joints"]} messages, 1 CSV files", output, StringComparison.Ordinal); // the topic exported
        Assert.Equal(check.StreamCounts["/arms/right/joints"] + 1, File.ReadAllLines(Path.Combine(csv, "arms_right_joints.csv")).Length);
    }

    [Fact]
    public void A_recording_in_a_missing_directory_is_one_line_and_nothing_runs()
    {
        var (code, output, error) = Cli.Run("run", RunProcess.Graph, "--virtual", "--duration", "1s", "--record", "/nonexistent-rc/run.mcap");

        Assert.Equal(2, code);
        Assert.Equal("--record: directory /nonexistent-rc does not exist" + Environment.NewLine, error);
        Assert.DoesNotContain("summary", output, StringComparison.Ordinal);
    }

    [Fact]
    public void A_recording_in_a_read_only_directory_is_one_line()
    {
        var (code, _, error) = Cli.Run("run", RunProcess.Graph, "--virtual", "--duration", "1s", "--record", "/proc/run.mcap");

        Assert.Equal(2, code);
        Assert.StartsWith("--record: cannot write in /proc", error, StringComparison.Ordinal);
        Assert.Single(error.Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries));
    }

    [Fact]
    public void An_existing_file_is_kept_without_force_and_replaced_with_it()
    {
        var file = Path.Combine(Directory.CreateTempSubdirectory("rc-rec-").FullName, "exists.mcap");
        File.WriteAllText(file, "keep me");

        var (code, _, error) = Cli.Run("run", RunProcess.Graph, "--virtual", "--duration", "1s", "--record", file);
        Assert.Equal(2, code);
        Assert.Equal($"--record {file}: the file exists; add --force to replace it" + Environment.NewLine, error);
        Assert.Equal("keep me", File.ReadAllText(file));

        var (forced, output, _) = Cli.Run("run", RunProcess.Graph, "--virtual", "--duration", "1s", "--record", file, "--force", "--record-decimate", "10");
        Assert.Equal(0, forced);
        Assert.Contains($"recording: {file}: ", output, StringComparison.Ordinal);
        var check = McapCheck.Read(file);
        Assert.Null(check.Error);
        Assert.Equal(1000, check.IndexedCounts["/arms/left/joints"]);
        Assert.Equal(100, check.IndexedCounts["/graph/signals"]); // decimated by 10
    }

    [Fact]
    public void Exporting_a_file_that_is_not_mcap_is_one_line_naming_it()
    {
        var dir = Directory.CreateTempSubdirectory("rc-rec-").FullName;
        var file = Path.Combine(dir, "report.json");
        File.WriteAllText(file, "{}");

        var (code, _, error) = Cli.Run("export", file, "--csv", Path.Combine(dir, "csv"));

        Assert.Equal(2, code);
        Assert.Equal($"{file}: not an MCAP file (it does not start with the MCAP magic)" + Environment.NewLine, error);
        Assert.False(Directory.Exists(Path.Combine(dir, "csv")));
    }

    [Fact]
    public void Exporting_a_topic_the_file_lacks_is_one_line_listing_those_it_has()
    {
        var dir = Directory.CreateTempSubdirectory("rc-rec-").FullName;
        var file = Path.Combine(dir, "run.mcap");
        Assert.Equal(0, Cli.Run("run", RunProcess.Graph, "--virtual", "--duration", "200ms", "--record", file).Code);

        var (code, _, error) = Cli.Run("export", file, "--csv", Path.Combine(dir, "csv"), "--topics", "/nope");

        Assert.Equal(2, code);
        Assert.StartsWith("--topics: run.mcap has no topic /nope (it has /graph/signals, ", error, StringComparison.Ordinal);
    }

    [Fact]
    public void Replaying_a_file_that_is_not_mcap_or_is_missing_is_one_line_and_nothing_is_served()
    {
        var dir = Directory.CreateTempSubdirectory("rc-rec-").FullName;
        var notes = Path.Combine(dir, "notes.txt");
        File.WriteAllText(notes, "not a recording");

        var (code, output, error) = Cli.Run("console", "--replay", notes);
        Assert.Equal(2, code);
        Assert.Equal($"--replay {notes}: not an MCAP file (it does not start with the MCAP magic)" + Environment.NewLine, error);
        Assert.DoesNotContain("http", output, StringComparison.Ordinal);

        var missing = Path.Combine(dir, "missing.mcap");
        (code, _, error) = Cli.Run("console", "--replay", missing);
        Assert.Equal(2, code);
        Assert.Equal($"--replay {missing}: no such file" + Environment.NewLine, error);

        (code, _, error) = Cli.Run("console", RunProcess.Graph, "--replay", notes);
        Assert.Equal(2, code);
        Assert.Equal("console: give a graph file or --replay, not both" + Environment.NewLine, error);
    }
}
