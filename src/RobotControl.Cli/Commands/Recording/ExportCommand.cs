using System.CommandLine;
using RobotControl.Cli.Options;
using RobotControl.Host.Recording;
using RobotControl.Host.Recording.Mcap;

namespace RobotControl.Cli.Commands.Recording;

/// <summary>
/// <c>robotctl export &lt;file.mcap&gt; --csv &lt;dir&gt; [--topics /a,/b]</c>: a recording as one CSV per topic, time in
/// seconds from the start (MATLAB, pandas). A file cut short is exported up to its last complete chunk, and said so.
/// </summary>
internal sealed class ExportCommand : ICliCommand
{
    /// <inheritdoc />
    public Command Build()
    {
        var file = new Argument<FileInfo>("file") { Description = "An MCAP recording (robotctl run --record)" };
        var csv = CliOption.OutputDirectory("--csv", "-o", "Write one CSV per topic into this directory");
        var topics = new Option<string[]>("--topics") { Description = "Only these topics, e.g. /arms/right/joints,/graph/signals", AllowMultipleArgumentsPerToken = true, Arity = ArgumentArity.ZeroOrMore };
        var command = new Command("export", "Exports a recording (MCAP) as CSV, one file per topic, time in seconds from the start.");
        command.Arguments.Add(file);
        command.Options.Add(csv);
        command.Options.Add(topics);
        command.SetAction(parse => Run(
            parse.GetValue(file)!.FullName,
            parse.GetValue(csv)!.FullName,
            [.. (parse.GetValue(topics) ?? []).SelectMany(t => t.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))],
            parse.InvocationConfiguration.Output,
            parse.InvocationConfiguration.Error));
        return command;
    }

    /// <summary>Opens <paramref name="path"/>, saying in one line why it cannot be read, or that it was cut short; null when it cannot be read.</summary>
    private static McapFile? OpenOrSay(string path, TextWriter error)
    {
        try
        {
            var file = McapFile.Open(path);
            if (file.Truncated is { } truncated)
            {
                error.WriteLine(truncated);
            }

            return file;
        }
        catch (InvalidDataException ex)
        {
            error.WriteLine(ex.Message);
            return null;
        }
    }

    /// <summary>Runs the command; returns the exit code (0 ok, 2 bad input).</summary>
    internal static int Run(string path, string directory, IReadOnlyList<string> topics, TextWriter output, TextWriter error)
    {
        using var file = OpenOrSay(path, error);
        if (file is null)
        {
            return 2;
        }

        try
        {
            var (files, rows) = CsvExport.Write(file, directory, topics.Count == 0 ? null : topics);
            output.WriteLine($"{Path.GetFileName(path)}: {rows} messages, {files.Count} CSV files in {directory}");
            return 0;
        }
        catch (InvalidDataException ex)
        {
            error.WriteLine($"{ex.Message}; no CSV file was replaced");
            return 2;
        }
        catch (ArgumentException ex)
        {
            error.WriteLine(ex.Message);
            return 2;
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            error.WriteLine($"--csv {directory}: {ex.Message}");
            return 2;
        }
    }
}
