namespace RobotControl.Plugins.Sdk.Ports;

/// <summary>Description of one declared input or output, for wiring, validation and display.</summary>
/// <param name="Name">Port name, unique per direction within the plug-in (may contain dots, e.g. <c>right.elbow</c>).</param>
/// <param name="Index">Declaration index (the handle's index).</param>
/// <param name="Units">Units of the value, e.g. <c>mm</c>, <c>rad</c>, <c>N</c>, or empty.</param>
/// <param name="Description">What the value means.</param>
/// <param name="InitialValue">Value before anything is written (inputs: also the value of an unwired input).</param>
/// <param name="SafeValue">Outputs: what the output shows after a fault or a non-finite value.</param>
public sealed record PortInfo(string Name, int Index, string Units, string Description, double InitialValue, SafeValue SafeValue);
