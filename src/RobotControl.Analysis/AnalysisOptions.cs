using RobotControl.Analysis.Sweep;
using RobotControl.Analysis.Workspace;

namespace RobotControl.Analysis;

/// <summary>What <see cref="CapabilityAnalyzer"/> computes.</summary>
public sealed record AnalysisOptions
{
    /// <summary>The grid to sweep; null for the robot file's reference cross-section.</summary>
    public SweepSpecification? Sweep { get; init; }

    /// <summary>Also evaluate velocity and force with the limits applied to the motors behind the couplings.</summary>
    public bool CouplingAware { get; init; }

    /// <summary>Compute workspace volumes (the slowest part).</summary>
    public bool Workspace { get; init; } = true;

    /// <summary>Finer workspace cell size h, mm (volumes are extrapolated from h and 2h).</summary>
    public double WorkspaceVoxelMm { get; init; } = WorkspaceCalculator.DefaultVoxelMm;
}
