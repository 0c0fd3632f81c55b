namespace RobotControl.Plugins.Sdk.Ports;

/// <summary>
/// Handle of a declared input: an index into the plug-in's input values, so reading it in
/// <see cref="Plugin.Tick(in TickContext)"/> is an array access (no lookup, no allocation).
/// </summary>
/// <param name="Index">Position of the input in declaration order.</param>
public readonly record struct InputPort(int Index);
