using System.CommandLine;

namespace RobotControl.Cli.Commands;

/// <summary>
/// One top-level <c>robotctl</c> command. Implementations are found by reflection at start-up, so adding a command
/// means adding a class in this folder (or a feature folder), nothing else.
/// </summary>
internal interface ICliCommand
{
    /// <summary>Builds the command with its options, arguments and action.</summary>
    Command Build();
}
