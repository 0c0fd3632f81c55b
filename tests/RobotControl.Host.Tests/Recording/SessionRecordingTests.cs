using System.Globalization;
using RobotControl.Host.Harness;
using RobotControl.Host.Recording;
using RobotControl.Host.Recording.Mcap;
using RobotControl.Kinematics.Forward;
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
                Record = new RecordingOptions { Path = path, OpenStream = p => new FullDisk(File.Create(p), 3 << 20), Stopped = told.Add },
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
    public void A_tick_with_the_recorders_tap_allocates_nothing()
    {
        var path = Path.Combine(Directory.CreateTempSubdirectory("rc-rec-").FullName, "alloc.mcap");
        long allocated = 0, measured = 0;
        HeadlessRun.RunVirtual(
            new RunOptions { GraphPath = Graphs.Path("teleop-lb.json"), Duration = TimeSpan.FromSeconds(2), Record = new RecordingOptions { Path = path } },
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
                new RunOptions { GraphPath = Graphs.Path("teleop-lb.json"), Duration = TimeSpan.FromSeconds(8), Record = new RecordingOptions { Path = Path } },
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
