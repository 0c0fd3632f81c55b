using System.Globalization;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Sampling;

namespace RobotControl.Plugins.Standard.Recording;

/// <summary>
/// Drives a graph from a recording: every column of the CSV but <c>time_s</c> becomes an output named after it (e.g.
/// a recorder's <c>touch_right.x</c> column is output <c>touch_right.x</c> of this instance), valued at the loop time
/// by interpolation (or hold) between rows. The file is read when the instance is created.
/// </summary>
[PluginType("playback", Description = "Plays a CSV recording back as outputs named after its columns.")]
public sealed class PlaybackPlugin : Plugin<PlaybackSettings>
{
    private readonly double[] _time;
    private readonly double[][] _rows;
    private readonly OutputPort[] _outputs;
    private int _hint;

    /// <summary>Creates the plug-in and reads the recording.</summary>
    /// <exception cref="FormatException">The file is malformed (the message names the line).</exception>
    public PlaybackPlugin(PlaybackSettings settings, PluginContext context)
        : base(settings, context)
    {
        var path = Context.ResolvePath(Settings.Path);
        using var lines = File.ReadLines(path).Where(l => l.Length > 0 && !l.StartsWith('#')).GetEnumerator();
        if (!lines.MoveNext())
        {
            throw new FormatException($"{path}: empty recording");
        }

        var header = lines.Current.Split(',').Select(h => h.Trim()).ToArray();
        var timeColumn = Array.IndexOf(header, "time_s");
        if (timeColumn < 0)
        {
            throw new FormatException($"{path}: the header has no time_s column");
        }

        var columns = Enumerable.Range(0, header.Length).Where(c => c != timeColumn).ToArray();
        _outputs = [.. columns.Select(c => DeclareOutput(header[c], SafeValue.HoldLastFinite, "", $"recorded {header[c]}"))];
        var time = new List<double>();
        var rows = new List<double[]>();
        var lineNumber = 1;
        while (lines.MoveNext())
        {
            lineNumber++;
            var cells = lines.Current.Split(',');
            if (cells.Length != header.Length)
            {
                throw new FormatException($"{path}: row {lineNumber} has {cells.Length} cells, the header {header.Length}");
            }

            var values = new double[cells.Length];
            for (var i = 0; i < cells.Length; i++)
            {
                if (!double.TryParse(cells[i], NumberStyles.Float, CultureInfo.InvariantCulture, out values[i]))
                {
                    throw new FormatException($"{path}: row {lineNumber}: '{cells[i]}' is not a number");
                }
            }

            if (time.Count > 0 && values[timeColumn] <= time[^1])
            {
                throw new FormatException($"{path}: row {lineNumber}: time does not increase");
            }

            time.Add(values[timeColumn]);
            rows.Add([.. columns.Select(c => values[c])]);
        }

        if (rows.Count == 0)
        {
            throw new FormatException($"{path}: the recording has no rows");
        }

        _time = [.. time];
        _rows = [.. rows];
    }

    /// <summary>Length of the recording, seconds.</summary>
    public double DurationSeconds => _time[^1] - _time[0];

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        var t = _time[0] + context.TimeSeconds + Settings.TimeOffsetS;
        if (Settings.Repeat && DurationSeconds > 0 && t > _time[^1])
        {
            t = _time[0] + ((t - _time[0]) % DurationSeconds);
        }

        var i = SampleTimes.IndexAtOrBefore(_time, t, ref _hint);
        var a = _rows[i];
        var interpolate = Settings.Interpolate && i < _time.Length - 1 && t > _time[i];
        var f = interpolate ? (t - _time[i]) / (_time[i + 1] - _time[i]) : 0.0;
        var b = interpolate ? _rows[i + 1] : a;
        for (var k = 0; k < _outputs.Length; k++)
        {
            Write(_outputs[k], a[k] + (f * (b[k] - a[k])));
        }
    }
}
