namespace RobotControl.Plugins.Sdk.Ports;

/// <summary>Handle of a declared output: an index into the plug-in's output values (see <see cref="InputPort"/>).</summary>
/// <param name="Index">Position of the output in declaration order.</param>
public readonly record struct OutputPort(int Index);
