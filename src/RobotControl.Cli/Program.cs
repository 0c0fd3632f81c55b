namespace RobotControl.Cli;

/// <summary>Entry point of <c>robotctl</c>.</summary>
internal static class Program
{
    private static int Main(string[] args) => CliApp.Invoke(args, Console.Out, Console.Error);
}
