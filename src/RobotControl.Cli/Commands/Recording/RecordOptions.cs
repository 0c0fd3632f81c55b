using System.CommandLine;
using RobotControl.Cli.Options;
using RobotControl.Host.Recording;
using RobotControl.Host.Recording.Mcap;

namespace RobotControl.Cli.Commands.Recording;

/// <summary>
/// The recording options <c>run</c> and <c>console</c> share: <c>--record &lt;file.mcap&gt;</c> (checked while parsing:
/// the directory exists and takes a file), <c>--record-decimate N</c>, <c>--record-compression zstd|none</c> and
/// <c>--force</c> (replace a file that exists).
/// </summary>
internal sealed class RecordOptions
{
    private RecordOptions(Option<FileInfo?> path, Option<int> decimate, Option<string> compression, Option<bool> force)
    {
        Path = path;
        Decimate = decimate;
        Compression = compression;
        Force = force;
    }

    public Option<FileInfo?> Path { get; }

    public Option<int> Decimate { get; }

    public Option<string> Compression { get; }

    public Option<bool> Force { get; }

    /// <summary>Makes the options.</summary>
    public static RecordOptions Create() => new(
        CliOption.OutputFile("--record", "Record the session to this MCAP file (every signal, joints, bus, run levels, trips; docs/recording.md)"),
        CliOption.Number("--record-decimate", "With --record: record the graph's signals, input devices and tool poses every N ticks (joints every tick)", 1, 1000, 1),
        Compressions(),
        new Option<bool>("--force") { Description = "With --record: replace the file if it exists" });

    /// <summary>Adds the options to <paramref name="command"/>.</summary>
    public void AddTo(Command command)
    {
        command.Options.Add(Path);
        command.Options.Add(Decimate);
        command.Options.Add(Compression);
        command.Options.Add(Force);
    }

    /// <summary>What the user asked for; null without <c>--record</c>.</summary>
    public RecordRequest? Value(ParseResult parse) =>
        parse.GetValue(Path) is { } file ? new RecordRequest(file.FullName, parse.GetValue(Decimate), parse.GetValue(Compression) == "none" ? McapCompression.None : McapCompression.Zstd, parse.GetValue(Force)) : null;

    private static Option<string> Compressions()
    {
        var option = new Option<string>("--record-compression") { Description = "With --record: the chunks' compression, zstd (default) or none", DefaultValueFactory = _ => McapCompression.Zstd };
        option.AcceptOnlyFromAmong(McapCompression.Zstd, "none");
        return option;
    }
}

/// <summary>A recording asked for on the command line.</summary>
/// <param name="Path">The file (full path).</param>
/// <param name="Decimate">The <c>--record-decimate</c> value.</param>
/// <param name="Compression">The chunks' compression (<see cref="McapCompression"/>).</param>
/// <param name="Force">The <c>--force</c> flag.</param>
internal sealed record RecordRequest(string Path, int Decimate, string Compression, bool Force)
{
    /// <summary>The session layer's options; a stop of the recording is told on <paramref name="error"/> as it happens.</summary>
    /// <exception cref="FormatException">The file exists and <c>--force</c> was not given (one line).</exception>
    public RecordingOptions Options(TextWriter error)
    {
        if (File.Exists(Path) && !Force)
        {
            throw new FormatException($"--record {Path}: the file exists; add --force to replace it");
        }

        return new RecordingOptions { Path = Path, Decimate = Decimate, Compression = Compression, Stopped = line => error.WriteLine(line) };
    }
}
