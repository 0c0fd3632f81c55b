using System.CommandLine;
using System.CommandLine.Invocation;
using RobotControl.Cli.Commands;

namespace RobotControl.Cli;

/// <summary>
/// <c>robotctl</c>'s command tree and its one invocation path: a bad command line gets its errors (one line each,
/// naming the option) without the help text, and whatever a command throws becomes one line on the error stream and
/// a non-zero exit code, never a stack trace.
/// </summary>
internal static class CliApp
{
    /// <summary>Exit code of a bad command line or a refused input.</summary>
    public const int BadInput = 2;

    /// <summary>Exit code of an unexpected failure inside a command.</summary>
    public const int InternalError = 70;

    /// <summary>The root command with every <see cref="ICliCommand"/> of this assembly.</summary>
    public static RootCommand BuildRoot()
    {
        var root = new RootCommand("robotctl: RobotControl's command-line tool (analysis, bus tools, virtual robot, headless runs).");
        foreach (var type in typeof(CliApp).Assembly.GetTypes()
                     .Where(t => typeof(ICliCommand).IsAssignableFrom(t) && t is { IsAbstract: false, IsInterface: false })
                     .OrderBy(t => t.Name, StringComparer.Ordinal))
        {
            root.Subcommands.Add(((ICliCommand)Activator.CreateInstance(type)!).Build());
        }

        root.Options.OfType<VersionOption>().Single().Action = new ProductVersionAction();
        return root;
    }

    /// <summary>Parses and runs <paramref name="args"/>; returns the exit code.</summary>
    public static int Invoke(string[] args, TextWriter output, TextWriter error)
    {
        ArgumentNullException.ThrowIfNull(args);
        ArgumentNullException.ThrowIfNull(output);
        ArgumentNullException.ThrowIfNull(error);
        var parse = BuildRoot().Parse(args);
        if (parse.Errors.Count > 0)
        {
            foreach (var e in parse.Errors.Select(e => e.Message).Distinct(StringComparer.Ordinal))
            {
                error.WriteLine(OneLine(e));
            }

            return BadInput;
        }

        try
        {
            return parse.Invoke(new InvocationConfiguration { Output = output, Error = error, EnableDefaultExceptionHandler = false });
        }
        catch (Exception ex) when (ex is IOException or FormatException or ArgumentException or InvalidOperationException or UnauthorizedAccessException
                                       or KeyNotFoundException or OverflowException or Definitions.Loading.RobotDataException or Runtime.Graph.GraphException)
        {
            error.WriteLine($"error: {OneLine(ex.Message)}");
            return BadInput;
        }
        catch (Exception ex) when (ex is not OutOfMemoryException)
        {
            error.WriteLine($"internal error ({ex.GetType().Name}): {OneLine(ex.Message)}");
            return InternalError;
        }
    }

    private static string OneLine(string message) => message.ReplaceLineEndings(" ");
}
