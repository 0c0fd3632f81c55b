namespace RobotControl.Definitions.Model;

/// <summary>A kinematic (revolute) joint with its limits in radians.</summary>
/// <param name="Name">Joint name, e.g. <c>elbow</c>; motors and graph signals are named after it.</param>
/// <param name="Symbol">The design documents' symbol, e.g. <c>phi4</c>.</param>
/// <param name="MinRad">Lower limit, radians.</param>
/// <param name="MaxRad">Upper limit, radians (never below <paramref name="MinRad"/>).</param>
/// <param name="RangeSource">Where the range comes from (design data or a documented choice).</param>
public sealed record JointDefinition(string Name, string Symbol, double MinRad, double MaxRad, string RangeSource)
{
    /// <summary>Middle of the range, radians.</summary>
    public double MidRad => 0.5 * (MinRad + MaxRad);
}
