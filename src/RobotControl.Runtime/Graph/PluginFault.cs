namespace RobotControl.Runtime.Graph;

/// <summary>A plug-in that faulted: it is no longer ticked, its outputs hold their safe values.</summary>
/// <param name="Instance">The instance name.</param>
/// <param name="TickIndex">The tick on which it faulted.</param>
/// <param name="Time">Loop time of that tick.</param>
/// <param name="Message">What happened (exception type and message).</param>
/// <param name="Exception">The exception, when there was one.</param>
public sealed record PluginFault(string Instance, long TickIndex, TimeSpan Time, string Message, Exception? Exception);
