namespace RobotControl.Analysis;

/// <summary>A progress report: which stage finished or started, and the overall fraction done.</summary>
/// <param name="Stage">Human-readable stage, e.g. <c>workspace volumes</c>.</param>
/// <param name="Fraction">Overall fraction done, 0..1.</param>
/// <param name="Elapsed">Time the finished stage took, or null when the stage is starting.</param>
public sealed record AnalysisProgress(string Stage, double Fraction, TimeSpan? Elapsed);
