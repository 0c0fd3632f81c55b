using System.Globalization;
using RobotControl.Plugins.Sdk.Sampling;

namespace RobotControl.Plugins.Touch.Simulation;

/// <summary>
/// A scripted (or recorded) hand trajectory: keyframes of where the hand holds the stylus, interpolated linearly,
/// with button states held from the last keyframe. CSV with a header naming columns
/// <c>time_s,x_mm,y_mm,z_mm,roll_rad,pitch_rad,yaw_rad,button1,button2</c> (any order; orientation and buttons
/// optional; lines starting with <c>#</c> are comments). A recording of a Touch (the recorder's CSV) is read with a
/// column prefix: <c>time_s</c> and <c>&lt;prefix&gt;x</c>, <c>&lt;prefix&gt;y</c>, ... <c>&lt;prefix&gt;button2</c>
/// (the Touch's own outputs, mm and rad), e.g. prefix <c>touch_right.</c>.
/// </summary>
public sealed class HandScript
{
    private static readonly string[] RecordedColumns = ["x", "y", "z", "roll", "pitch", "yaw", "button1", "button2"];
    private readonly double[] _time;
    private readonly double[][] _values; // x, y, z, roll, pitch, yaw per keyframe
    private readonly bool[] _button1;
    private readonly bool[] _button2;

    private HandScript(double[] time, double[][] values, bool[] button1, bool[] button2)
    {
        _time = time;
        _values = values;
        _button1 = button1;
        _button2 = button2;
    }

    /// <summary>Time of the last keyframe, seconds.</summary>
    public double DurationSeconds => _time[^1];

    /// <summary>Number of keyframes.</summary>
    public int Count => _time.Length;

    /// <summary>Loads a script file.</summary>
    /// <exception cref="FormatException">The file is malformed (the message names the line).</exception>
    public static HandScript Load(string path, string columnPrefix = "")
    {
        ArgumentException.ThrowIfNullOrEmpty(path);
        return Parse(File.ReadLines(path), path, columnPrefix);
    }

    /// <summary>Parses script lines; <paramref name="source"/> names them in messages; a non-empty <paramref name="columnPrefix"/> reads a recording.</summary>
    /// <exception cref="FormatException">The text is malformed.</exception>
    public static HandScript Parse(IEnumerable<string> lines, string source, string columnPrefix = "")
    {
        ArgumentNullException.ThrowIfNull(columnPrefix);
        ArgumentNullException.ThrowIfNull(lines);
        string[]? header = null;
        var time = new List<double>();
        var values = new List<double[]>();
        var b1 = new List<bool>();
        var b2 = new List<bool>();
        int[] columns = [];
        var lineNumber = 0;
        foreach (var raw in lines)
        {
            lineNumber++;
            var line = raw.Trim();
            if (line.Length == 0 || line.StartsWith('#'))
            {
                continue;
            }

            var cells = line.Split(',');
            if (header is null)
            {
                header = [.. cells.Select(c => c.Trim())];
                string[] wanted = columnPrefix.Length == 0
                    ? ["time_s", "x_mm", "y_mm", "z_mm", "roll_rad", "pitch_rad", "yaw_rad", "button1", "button2"]
                    : ["time_s", .. RecordedColumns.Select(c => columnPrefix + c)];
                columns = [.. wanted.Select(w => Array.IndexOf(header, w))];
                if (columns[..4].Any(c => c < 0))
                {
                    throw new FormatException($"{source}:{lineNumber}: the header needs {string.Join(", ", wanted[..4])} columns");
                }

                continue;
            }

            if (cells.Length != header.Length)
            {
                throw new FormatException($"{source}:{lineNumber}: {cells.Length} cells, the header has {header.Length}");
            }

            double Cell(int column)
            {
                if (column < 0)
                {
                    return 0;
                }

                if (!double.TryParse(cells[column], NumberStyles.Float, CultureInfo.InvariantCulture, out var v) || !double.IsFinite(v))
                {
                    throw new FormatException($"{source}:{lineNumber}: '{cells[column]}' in column {header[column]} is not a finite number");
                }

                return v;
            }

            var t = Cell(columns[0]);
            if (time.Count > 0 && t <= time[^1])
            {
                throw new FormatException($"{source}:{lineNumber}: time {t} s does not increase");
            }

            time.Add(t);
            values.Add([Cell(columns[1]), Cell(columns[2]), Cell(columns[3]), Cell(columns[4]), Cell(columns[5]), Cell(columns[6])]);
            b1.Add(Cell(columns[7]) >= 0.5);
            b2.Add(Cell(columns[8]) >= 0.5);
        }

        if (time.Count < 2)
        {
            throw new FormatException($"{source}: a script needs at least two keyframes");
        }

        return new HandScript([.. time], [.. values], [.. b1], [.. b2]);
    }

    /// <summary>
    /// The hand pose at <paramref name="timeSeconds"/> (clamped to the script): position and orientation into
    /// <paramref name="pose"/> (x, y, z mm; roll, pitch, yaw rad), velocity (mm/s) into <paramref name="velocity"/>.
    /// Allocation-free; <paramref name="hint"/> speeds up the search for monotonic time.
    /// </summary>
    public void Sample(double timeSeconds, Span<double> pose, Span<double> velocity, out bool button1, out bool button2, ref int hint)
    {
        var t = Math.Clamp(timeSeconds, _time[0], _time[^1]);
        var i = Math.Min(SampleTimes.IndexAtOrBefore(_time, t, ref hint), _time.Length - 2); // the segment [i, i + 1]
        var dt = _time[i + 1] - _time[i];
        var f = (t - _time[i]) / dt;
        var a = _values[i];
        var b = _values[i + 1];
        for (var k = 0; k < 6; k++)
        {
            pose[k] = a[k] + (f * (b[k] - a[k]));
        }

        var moving = timeSeconds >= _time[0] && timeSeconds < _time[^1];
        for (var k = 0; k < 3; k++)
        {
            velocity[k] = moving ? (b[k] - a[k]) / dt : 0.0;
        }

        button1 = _button1[i];
        button2 = _button2[i];
        if (t >= _time[i + 1])
        {
            button1 = _button1[i + 1];
            button2 = _button2[i + 1];
        }
    }
}
