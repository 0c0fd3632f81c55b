namespace RobotControl.Runtime.Graph;

/// <summary>A connection from an output signal to an input signal (<c>instance.port</c> names).</summary>
/// <param name="From">The output, e.g. <c>ik_right.fx</c>.</param>
/// <param name="To">The input, e.g. <c>touch_right.force_x</c>.</param>
/// <param name="Delayed">True for a feedback wire: the input sees the output's value of the previous tick.</param>
/// <param name="Origin">Where the wire was declared (JSON path), for messages.</param>
public sealed record Wire(string From, string To, bool Delayed, string Origin = "");
