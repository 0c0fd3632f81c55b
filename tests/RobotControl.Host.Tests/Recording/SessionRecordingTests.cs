using RobotControl.Host.Session;
using System.Globalization;
using System.Text.Json;
using RobotControl.Host.Harness;
using RobotControl.Host.Recording;
using RobotControl.Host.Recording.Mcap;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Mirroring;
using RobotControl.Kinematics.Urdf;
using RobotControl.TestSupport;
using RobotControl.TestSupport.Mcap;

namespace RobotControl.Host.Tests.Recording;

/// <summary>
/// The main job (the two-arm teleoperation graph on the virtual robot) recorded to MCAP: the official reader reads
/// what the writer wrote, the CSV export reproduces the run report's tracking error, a full disk stops the recording
/// and not the run, and the loop's ticks allocate nothing with the recorder's tap on them.
/// </summary>
public sealed class SessionRecordingTests(SessionRecordingTests.MainJob job) : IClassFixture<SessionRecordingTests.MainJob>
{
    [Fact]
    public void The_official_reader_counts_every_topic_as_the_recorder_wrote_it()
    {
        var check = McapCheck.Read(job.Path);
        var written = job.Report.Recording!.PerTopic.ToDictionary(p => p.Key, p => (long)p.Value);

        Assert.Null(check.Error);
        Assert.True(check.Complete);
        Assert.Equal(written, check.StreamCounts);
        Assert.Equal(written, check.IndexedCounts);
        Assert.True(check.DataSectionCrcOk);
        Assert.Equal(0, check.BadJson);
        Assert.Equal(0, job.Report.Recording.DroppedRows);
        Assert.Equal(job.Report.Ticks, written["/arms/right/joints"]);
        Assert.Equal(job.Report.Ticks, written["/graph/signals"]);
        Assert.Equal(job.Report.Safety!.RunLevels.Count, written["/safety/run_level"]);
        Assert.Equal(1, written["/operator/commands"]); // the harness pressed the pedal
        Assert.Equal(["teleop-lb.json", "lb-1.0.json", "LB-1.0.urdf"], check.Attachments);
        Assert.Equal([McapCompression.Zstd], check.Compressions); // the default
        Assert.True(check.Schemas >= 10, $"{check.Schemas} schemas");
    }

    [Fact]
    public void The_csv_export_reproduces_the_reports_tracking_rms_and_max_to_a_tenth_of_a_percent()
    {
        using var contents = McapFile.Open(job.Path);
        var chain = new KinematicChain(ShippedRobots.Lb);
        var commanded = chain.CreateState();
        var reported = chain.CreateState();
        var joints = ShippedRobots.Lb.Joints.Select(j => j.Name).ToArray();
        double sum = 0, max = 0;
        long samples = 0;
        foreach (var arm in new[] { "right", "left" })
        {
            var table = CsvExport.Tabulate(contents, $"/arms/{arm}/joints");
            var tracking = Column(table, "tracking");
            var setpoints = joints.Select(j => Column(table, "setpoint_rad." + j)).ToArray();
            var positions = joints.Select(j => Column(table, "position_rad." + j)).ToArray();
            foreach (var row in table.Rows)
            {
                if (Value(row, tracking) == 0)
                {
                    continue;
                }

                commanded.Update([.. setpoints.Select(c => Value(row, c))]);
                reported.Update([.. positions.Select(c => Value(row, c))]);
                var error = (commanded.ToolPosition - reported.ToolPosition).Length;
                sum += error * error;
                max = Math.Max(max, error);
                samples++;
            }
        }

        var rms = Math.Sqrt(sum / samples);
        Assert.True(samples > job.Report.Ticks, $"{samples} tracked samples over two arms");
        Assert.InRange(rms, job.Report.TrackingRmsMm * 0.999, job.Report.TrackingRmsMm * 1.001);
        Assert.InRange(max, job.Report.TrackingMaxMm * 0.999, job.Report.TrackingMaxMm * 1.001);
    }

    [Fact]
    public void A_full_disk_stops_the_recording_says_so_once_and_the_run_goes_on()
    {
        var path = Path.Combine(Directory.CreateTempSubdirectory("rc-rec-").FullName, "full.mcap");
        var told = new List<string>();
        var report = HeadlessRun.Run(
            new RunOptions
            {
                GraphPath = Graphs.Path("teleop-lb.json"),
                Duration = TimeSpan.FromSeconds(2),
                TickCost = VirtualTickCost.Free,
                Record = new RecordingOptions { Path = path, OpenStream = p => new FullDisk(File.Create(p), 256 << 10), Stopped = told.Add },
            },
            TestPlugins.Catalog());

        Assert.Equal(2000, report.Ticks);
        Assert.Empty(report.Faults);
        var line = Assert.Single(told);
        Assert.Equal($"recording stopped: {path}: No space left on device; the run goes on", line);
        Assert.Equal(line, report.Recording!.Stopped);
        using var cut = McapFile.Open(path);
        Assert.NotNull(cut.Truncated);
        Assert.NotEmpty(cut.Messages()); // what reached the disk, up to the last complete chunk
    }

    [Fact]
    public void The_link_frames_on_tf_put_each_tool_where_the_recorded_joints_put_it()
    {
        using var file = McapFile.Open(job.Path);
        var robot = ShippedRobots.Lb;
        var chain = new KinematicChain(robot);
        var state = chain.CreateState();
        var children = Enumerable.Range(0, new UrdfLinkFrames(robot).Count).Select(new UrdfLinkFrames(robot).Child).Order().ToList();
        var joints = file.Channel("/arms/left/joints")!.Id;
        var tf = file.Channel(RecordingTopics.Transforms)!.Id;
        var measured = new Dictionary<ulong, double[]>();
        var withLinks = 0;
        foreach (var message in file.Messages([joints, tf]))
        {
            using var doc = JsonDocument.Parse(message.Data);
            if (message.ChannelId == joints)
            {
                measured[message.LogTimeNs] = [.. doc.RootElement.GetProperty("position_rad").EnumerateObject().Select(p => p.Value.GetDouble())];
                continue;
            }

            var frames = doc.RootElement.GetProperty("transforms").EnumerateArray().ToDictionary(t => t.GetProperty("child_frame_id").GetString()!);
            if (!frames.ContainsKey("left_tool"))
            {
                continue;
            }

            withLinks++;
            Assert.Equal(children, frames.Keys.Where(k => !k.EndsWith("_measured", StringComparison.Ordinal) && !k.EndsWith("_setpoint", StringComparison.Ordinal)).Order().ToList());
            state.Update(measured[message.LogTimeNs]);
            var expected = new ArmMirror(robot, "left").ModelToBody(state.ToolPose).Position * UrdfExport.MetresPerMm;
            var position = Vector3d.Zero;
            var rotation = Rotation3d.Identity;
            foreach (var frame in RootTo(frames, "left_tool"))
            {
                var t = frame.GetProperty("translation");
                var r = frame.GetProperty("rotation");
                position += rotation.Apply(new Vector3d(t.GetProperty("x").GetDouble(), t.GetProperty("y").GetDouble(), t.GetProperty("z").GetDouble()));
                rotation *= FromQuaternion(r.GetProperty("x").GetDouble(), r.GetProperty("y").GetDouble(), r.GetProperty("z").GetDouble(), r.GetProperty("w").GetDouble());
            }

            Assert.True((position - expected).Length < 1e-9, $"at {message.LogTimeNs}: {position} against {expected}");
        }

        Assert.Equal(job.Report.Ticks / 10, withLinks); // 100 Hz at a 1 kHz loop
    }

    [Fact]
    public void A_tick_with_the_recorders_tap_allocates_nothing()
    {
        var path = Path.Combine(Directory.CreateTempSubdirectory("rc-rec-").FullName, "alloc.mcap");
        long allocated = 0, measured = 0;
        HeadlessRun.RunVirtual(
            new RunOptions { GraphPath = Graphs.Path("teleop-lb.json"), Duration = TimeSpan.FromSeconds(2), Record = new RecordingOptions { Path = path }, TickCost = VirtualTickCost.Free },
            TestPlugins.Catalog(),
            new VirtualRunHooks
            {
                AroundTick = (loop, _) =>
                {
                    var before = GC.GetAllocatedBytesForCurrentThread();
                    loop.Step();
                    if (loop.TickCount > 500)
                    {
                        allocated += GC.GetAllocatedBytesForCurrentThread() - before;
                        measured++;
                    }
                },
            });

        Assert.True(measured > 1000, $"{measured} ticks measured");
        Assert.Equal(0, allocated);
        using var recorded = McapFile.Open(path);
        var joints = recorded.Channels.Values.Single(c => c.Topic == "/arms/right/joints").Id;
        Assert.Equal(2000, recorded.Messages([joints]).Count()); // the tap was on every tick measured
    }

    /// <summary>The transforms from the root down to <paramref name="link"/>, root first.</summary>
    private static List<JsonElement> RootTo(Dictionary<string, JsonElement> frames, string link)
    {
        var path = new List<JsonElement>();
        for (var current = link; frames.TryGetValue(current, out var frame); current = frame.GetProperty("parent_frame_id").GetString()!)
        {
            path.Insert(0, frame);
        }

        Assert.Equal("body", path[0].GetProperty("parent_frame_id").GetString());
        return path;
    }

    /// <summary>The rotation of unit quaternion (x, y, z, w), written out here: nothing of the recorder's conversion.</summary>
    private static Rotation3d FromQuaternion(double x, double y, double z, double w) => new(
        new Vector3d(1 - (2 * ((y * y) + (z * z))), 2 * ((x * y) + (z * w)), 2 * ((x * z) - (y * w))),
        new Vector3d(2 * ((x * y) - (z * w)), 1 - (2 * ((x * x) + (z * z))), 2 * ((y * z) + (x * w))),
        new Vector3d(2 * ((x * z) + (y * w)), 2 * ((y * z) - (x * w)), 1 - (2 * ((x * x) + (y * y)))));

    private static int Column(CsvExport.Table table, string name)
    {
        var i = table.Columns.ToList().IndexOf(name);
        Assert.True(i >= 0, $"no column {name} in {string.Join(",", table.Columns)}");
        return i;
    }

    private static double Value(string?[] row, int column) => double.Parse(row[column]!, CultureInfo.InvariantCulture);

    /// <summary>The main job recorded once for the class (8 s of loop time).</summary>
    public sealed class MainJob
    {
        public MainJob()
        {
            Path = System.IO.Path.Combine(Directory.CreateTempSubdirectory("rc-rec-").FullName, "main.mcap");
            Report = HeadlessRun.Run(
                new RunOptions { GraphPath = Graphs.Path("teleop-lb.json"), Duration = TimeSpan.FromSeconds(8), Record = new RecordingOptions { Path = Path }, TickCost = VirtualTickCost.Free },
                TestPlugins.Catalog());
        }

        public string Path { get; }

        public RunReport Report { get; }
    }

    /// <summary>A file stream on a disk that fills up after <c>capacity</c> bytes (ENOSPC).</summary>
    private sealed class FullDisk(Stream inner, long capacity) : Stream
    {
        private long _written;

        public override bool CanRead => false;

        public override bool CanSeek => false;

        public override bool CanWrite => true;

        public override long Length => _written;

        public override long Position { get => _written; set => throw new NotSupportedException(); }

        public override void Write(byte[] buffer, int offset, int count) => Write(buffer.AsSpan(offset, count));

        public override void Write(ReadOnlySpan<byte> buffer)
        {
            if (_written + buffer.Length > capacity)
            {
                throw new IOException("No space left on device");
            }

            inner.Write(buffer);
            _written += buffer.Length;
        }

        public override void Flush() => inner.Flush();

        public override int Read(byte[] buffer, int offset, int count) => throw new NotSupportedException();

        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();

        public override void SetLength(long value) => throw new NotSupportedException();

        protected override void Dispose(bool disposing)
        {
            if (disposing)
            {
                inner.Dispose();
            }

            base.Dispose(disposing);
        }
    }
}
