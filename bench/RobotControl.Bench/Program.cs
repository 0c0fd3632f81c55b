namespace RobotControl.Bench;

/// <summary>Dispatches <c>dotnet run -c Release --project bench/RobotControl.Bench -- &lt;name&gt; [options]</c>.</summary>
internal static class Program
{
    private static int Main(string[] args)
    {
        var commands = typeof(Program).Assembly.GetTypes()
            .Where(t => typeof(IBenchCommand).IsAssignableFrom(t) && t is { IsAbstract: false, IsInterface: false })
            .Select(t => (IBenchCommand)Activator.CreateInstance(t)!)
            .OrderBy(c => c.Name, StringComparer.Ordinal)
            .ToList();
        var command = args.Length > 0 ? commands.FirstOrDefault(c => c.Name == args[0]) : null;
        if (command is null)
        {
            Console.Error.WriteLine("usage: RobotControl.Bench <benchmark> [options]");
            foreach (var c in commands)
            {
                Console.Error.WriteLine($"  {c.Name,-12} {c.Description}");
            }

            return 2;
        }

        return command.Run(args[1..]);
    }
}
