namespace RobotControl.Definitions.Model;

/// <summary>
/// One standard Denavit-Hartenberg row: T(i-1 -> i) = Rz(theta) Tz(d) Tx(a) Rx(alpha), theta = q[JointIndex] + ThetaOffsetRad.
/// </summary>
/// <param name="AlphaRad">Link twist, radians.</param>
/// <param name="AMm">Link length, mm.</param>
/// <param name="DMm">Link offset, mm.</param>
/// <param name="ThetaOffsetRad">Fixed offset added to the joint variable, radians.</param>
/// <param name="JointIndex">Index of the joint variable driving this row, or -1 for a fixed row.</param>
public sealed record DhRow(double AlphaRad, double AMm, double DMm, double ThetaOffsetRad, int JointIndex)
{
    /// <summary>True when no joint drives this row.</summary>
    public bool IsFixed => JointIndex < 0;
}
