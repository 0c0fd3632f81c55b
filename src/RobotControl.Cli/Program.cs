using System.CommandLine;
using RobotControl.Cli.Commands;

namespace RobotControl.Cli;

/// <summary>Entry point of <c>robotctl</c>.</summary>
internal static class Program
{
    private static int Main(string[] args)
    {
        var root = new RootCommand("robotctl: RobotControl's command-line tool (analysis, bus tools, virtual robot, headless runs).");
        foreach (var type in typeof(Program).Assembly.GetTypes()
                     .Where(t => typeof(ICliCommand).IsAssignableFrom(t) && t is { IsAbstract: false, IsInterface: false })
                     .OrderBy(t => t.Name, StringComparer.Ordinal))
        {
            root.Subcommands.Add(((ICliCommand)Activator.CreateInstance(type)!).Build());
        }

        root.Options.OfType<VersionOption>().Single().Action = new ProductVersionAction();
        return root.Parse(args).Invoke();
    }
}
