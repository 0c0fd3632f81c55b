using RobotControl.Host.Session;
using System.Globalization;
using Microsoft.Extensions.Time.Testing;
using RobotControl.Host.Harness;
using RobotControl.Host.Recording;
using RobotControl.Host.Recording.Mcap;
using RobotControl.WebConsole.Replay;

namespace RobotControl.WebConsole.Tests.Replay;

/// <summary>
/// <c>robotctl console --replay</c>'s session: at playback time t the plots' ring holds what the recording holds at t
/// (read independently with the CSV export), at 0.25x to 4x, paused and after a seek; bad files are one line.
/// </summary>
public sealed class ReplaySessionTests(ReplaySessionTests.Recorded recorded) : IClassFixture<ReplaySessionTests.Recorded>
{
    [Fact]
    public void At_time_t_the_ring_shows_the_joint_values_the_recording_holds_at_t()
    {
        var time = new FakeTimeProvider();
        using var replay = new ReplaySession(recorded.Path, time);
        var arm = replay.Model.Arms[0];

        time.Advance(TimeSpan.FromSeconds(1.2345));
        replay.Pump();

        AssertRingAt(replay, arm.PositionSignals[3], arm.CommandSignals[3], 1.2345);
        Assert.Equal("PEDAL_DOWN", replay.Status.RobotState);
    }

    [Fact]
    public void Rate_pause_and_seek_move_the_position_as_asked()
    {
        var time = new FakeTimeProvider();
        using var replay = new ReplaySession(recorded.Path, time);
        var arm = replay.Model.Arms[1];

        replay.Rate(4);
        time.Advance(TimeSpan.FromSeconds(0.25));
        replay.Pump();
        Assert.Equal(1.0, replay.PositionSeconds, 9);
        replay.Play(false);
        time.Advance(TimeSpan.FromSeconds(1));
        replay.Pump();
        Assert.Equal(1.0, replay.PositionSeconds, 9);
        replay.Seek(0.4);
        replay.Rate(0.25);
        replay.Play(true);
        time.Advance(TimeSpan.FromSeconds(0.4));
        replay.Pump();
        Assert.Equal(0.5, replay.PositionSeconds, 9);
        AssertRingAt(replay, arm.PositionSignals[0], arm.CommandSignals[0], 0.5);
        Assert.Throws<ArgumentOutOfRangeException>(() => replay.Rate(5));
    }

    [Fact]
    public void A_file_that_is_not_mcap_is_one_line_naming_it()
    {
        var path = System.IO.Path.Combine(Directory.CreateTempSubdirectory("rc-replay-").FullName, "notes.txt");
        File.WriteAllText(path, "not a recording");

        var ex = Assert.Throws<InvalidDataException>(() => new ReplaySession(path, new FakeTimeProvider()));

        Assert.Equal($"{path}: not an MCAP file (it does not start with the MCAP magic)", ex.Message);
    }

    [Fact]
    public void A_file_cut_short_plays_up_to_its_last_complete_chunk_and_says_so()
    {
        var path = System.IO.Path.Combine(Directory.CreateTempSubdirectory("rc-replay-").FullName, "cut.mcap");
        var bytes = File.ReadAllBytes(recorded.Path);
        File.WriteAllBytes(path, bytes[..(bytes.Length / 2)]);

        var time = new FakeTimeProvider();
        using var replay = new ReplaySession(path, time);
        time.Advance(TimeSpan.FromSeconds(10));
        replay.Pump();

        Assert.Contains("cut short", replay.Truncated, StringComparison.Ordinal);
        Assert.InRange(replay.DurationSeconds, 0.1, 1.9);
        Assert.Equal(replay.DurationSeconds, replay.PositionSeconds);
    }

    /// <summary>The ring's last row equals the recording's last signals row at or before <paramref name="t"/>, and its commanded joint the arm's setpoint then.</summary>
    private void AssertRingAt(ReplaySession replay, string position, string command, double t)
    {
        var slice = replay.Signals.Read(0, [replay.Signals.IndexOf(position), replay.Signals.IndexOf(command)], int.MaxValue);
        using var contents = McapFile.Open(recorded.Path);
        var signals = CsvExport.Tabulate(contents, RecordingTopics.Signals);
        var row = signals.Rows.Last(r => Seconds(r[0]) <= t + 1e-12);
        Assert.Equal(Seconds(row[0]), slice.Times[^1], 12);
        Assert.Equal(Seconds(row[signals.Columns.ToList().IndexOf(position)]), slice.Values[0][^1]);
        var parts = command.Split('.'); // robot.{arm}.{joint}.command
        var joints = CsvExport.Tabulate(contents, RecordingTopics.Joints(parts[1]));
        var setpoint = joints.Rows.Last(r => Seconds(r[0]) <= Seconds(row[0]) + 1e-12);
        Assert.Equal(Seconds(setpoint[joints.Columns.ToList().IndexOf("setpoint_rad." + parts[2])]), slice.Values[1][^1]);
    }

    private static double Seconds(string? text) => double.Parse(text!, CultureInfo.InvariantCulture);

    /// <summary>The main job recorded once (2 s, every signal at the loop rate).</summary>
    public sealed class Recorded
    {
        public Recorded()
        {
            Path = System.IO.Path.Combine(Directory.CreateTempSubdirectory("rc-replay-").FullName, "main.mcap");
            HeadlessRun.Run(new RunOptions { GraphPath = System.IO.Path.Combine(ConsoleFixture.RepoRoot, "graphs", "teleop-lb.json"), Duration = TimeSpan.FromSeconds(2), Record = new RecordingOptions { Path = Path }, TickCost = VirtualTickCost.Free }, ConsoleFixture.Catalog());
        }

        public string Path { get; }
    }
}
