namespace RobotControl.Cli.Tests.Commands.Run;

/// <summary>Tests that run a robot in real time run one at a time (and not next to each other's CPU load).</summary>
[CollectionDefinition(RunProcess.Collection, DisableParallelization = true)]
public sealed class RealtimeRunsCollection;
