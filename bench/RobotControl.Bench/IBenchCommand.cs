namespace RobotControl.Bench;

/// <summary>One benchmark, selected by its <see cref="Name"/> as the first command-line argument. Found by reflection.</summary>
internal interface IBenchCommand
{
    /// <summary>The name used on the command line, e.g. <c>ik</c>.</summary>
    string Name { get; }

    /// <summary>One-line description for the usage text.</summary>
    string Description { get; }

    /// <summary>Runs the benchmark with the remaining arguments; returns the process exit code.</summary>
    int Run(string[] args);
}
