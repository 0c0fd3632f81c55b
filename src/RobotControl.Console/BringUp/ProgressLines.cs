using System.Text;

namespace RobotControl.WebConsole.BringUp;

/// <summary>
/// The lines a bring-up step prints (the commissioner's and the calibrator's progress, as the CLI prints them), kept
/// numbered for the page to fetch the ones it has not shown. Thread-safe: the step's thread writes, the server reads.
/// </summary>
public sealed class ProgressLines : TextWriter
{
    private readonly Lock _gate = new();
    private readonly List<string> _lines = [];
    private readonly StringBuilder _partial = new();

    /// <inheritdoc />
    public override Encoding Encoding => Encoding.UTF8;

    /// <summary>Lines so far.</summary>
    public int Count
    {
        get
        {
            lock (_gate)
            {
                return _lines.Count;
            }
        }
    }

    /// <summary>The last complete line, or null.</summary>
    public string? Last
    {
        get
        {
            lock (_gate)
            {
                return _lines.Count == 0 ? null : _lines[^1];
            }
        }
    }

    /// <inheritdoc />
    public override void Write(char value)
    {
        lock (_gate)
        {
            if (value == '\n')
            {
                _lines.Add(_partial.ToString().TrimEnd('\r'));
                _partial.Clear();
            }
            else
            {
                _partial.Append(value);
            }
        }
    }

    /// <inheritdoc />
    public override void WriteLine(string? value)
    {
        lock (_gate)
        {
            _lines.Add(_partial.Append(value).ToString());
            _partial.Clear();
        }
    }

    /// <summary>The lines numbered above <paramref name="after"/> (1 is the first), with their numbers.</summary>
    public IReadOnlyList<ProgressLine> After(int after)
    {
        lock (_gate)
        {
            var from = Math.Clamp(after, 0, _lines.Count);
            return [.. _lines.Skip(from).Select((text, i) => new ProgressLine(from + i + 1, text))];
        }
    }
}

/// <summary>One progress line.</summary>
/// <param name="Sequence">Its number, 1 for the first of the session.</param>
/// <param name="Text">The line.</param>
public sealed record ProgressLine(int Sequence, string Text);
