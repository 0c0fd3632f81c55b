using System.Globalization;
using System.Text;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Exchange;
using RobotControl.Plugins.Sdk.Observation;

namespace RobotControl.Plugins.Standard.Recording;

/// <summary>
/// Records every output signal of the graph with its loop time to a CSV file (header <c>time_s,instance.port,...</c>)
/// that a spreadsheet or plotting tool opens directly and <see cref="PlaybackPlugin"/> plays back. The loop copies a
/// row into a lock-free ring (no allocation, no I/O); a background thread formats and writes it.
/// </summary>
[PluginType("recorder", Description = "Records every signal with timestamps to a CSV file.")]
public sealed class RecorderPlugin : Plugin<RecorderSettings>, ISignalObserver
{
    private SignalView? _view;
    private SampleRing? _ring;
    private Thread? _writer;
    private volatile bool _stopping;
    private long _rows;

    /// <summary>Creates the plug-in.</summary>
    public RecorderPlugin(RecorderSettings settings, PluginContext context)
        : base(settings, context)
    {
    }

    /// <summary>Rows handed to the writer.</summary>
    public long Rows => Interlocked.Read(ref _rows);

    /// <summary>Rows dropped because the writer fell behind.</summary>
    public long Dropped => _ring?.Dropped ?? 0;

    /// <inheritdoc />
    public void Attach(SignalView view) => _view = view ?? throw new ArgumentNullException(nameof(view));

    /// <inheritdoc />
    public override void Start(in TickContext context)
    {
        var view = _view ?? throw new InvalidOperationException($"'{Name}' was not attached to a graph");
        _ring = new SampleRing(view.Names.Count + 1, Settings.BufferRows);
        var path = Context.ResolvePath(Settings.Path);
        Directory.CreateDirectory(System.IO.Path.GetDirectoryName(path)!);
        var stream = new StreamWriter(path, false, new UTF8Encoding(false), 1 << 16);
        stream.WriteLine("time_s," + string.Join(",", view.Names));
        _stopping = false;
        _writer = new Thread(() => WriteRows(stream, _ring)) { Name = $"recorder {Name}", IsBackground = true };
        _writer.Start();
    }

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        if (context.Index % Settings.EveryTicks != 0)
        {
            return;
        }

        var row = _ring!.BeginWrite();
        if (row.IsEmpty)
        {
            return;
        }

        row[0] = context.TimeSeconds;
        _view!.Values.CopyTo(row[1..]);
        _ring.EndWrite();
        Interlocked.Increment(ref _rows);
    }

    /// <inheritdoc />
    public override void Stop()
    {
        _stopping = true;
        _writer?.Join();
        _writer = null;
    }

    private void WriteRows(StreamWriter stream, SampleRing ring)
    {
        using (stream)
        {
            var row = new double[ring.Width];
            var text = new StringBuilder(row.Length * 12);
            while (true)
            {
                var wrote = false;
                while (ring.TryRead(row))
                {
                    text.Clear();
                    for (var i = 0; i < row.Length; i++)
                    {
                        if (i > 0)
                        {
                            text.Append(',');
                        }

                        text.Append(row[i].ToString("R", CultureInfo.InvariantCulture));
                    }

                    stream.WriteLine(text);
                    wrote = true;
                }

                if (_stopping && ring.Count == 0)
                {
                    break;
                }

                if (!wrote)
                {
                    Thread.Sleep(5);
                }
            }
        }
    }
}
