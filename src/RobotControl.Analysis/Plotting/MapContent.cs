namespace RobotControl.Analysis.Plotting;

/// <summary>What one map shows.</summary>
/// <param name="Values">One value per sweep point.</param>
/// <param name="Quantity">Short name, e.g. <c>Fx</c>.</param>
/// <param name="Description">What it is, e.g. <c>largest holding force along x</c>.</param>
/// <param name="Units">Units, e.g. <c>N</c>.</param>
/// <param name="Requirement">A requirement to mark on the map (the value must reach it), or null.</param>
internal sealed record MapContent(IReadOnlyList<double> Values, string Quantity, string Description, string Units, double? Requirement);
