namespace RobotControl.Analysis.Workspace;

/// <summary>Workspace volumes extrapolated to zero cell size (2·V(h) − V(2h)), with the two raw results.</summary>
/// <param name="ArmCm3">One arm (both arms are mirror images, so equal).</param>
/// <param name="UnionCm3">Points either arm reaches.</param>
/// <param name="SharedCm3">Points both arms reach.</param>
/// <param name="Fine">Raw volumes at cell size h.</param>
/// <param name="Coarse">Raw volumes at cell size 2h.</param>
public sealed record WorkspaceVolumes(
    double ArmCm3,
    double UnionCm3,
    double SharedCm3,
    WorkspaceGridVolumes Fine,
    WorkspaceGridVolumes Coarse);

/// <summary>Numerical workspace volumes of the tool tip at one resolution.</summary>
/// <param name="ArmCm3">One arm.</param>
/// <param name="UnionCm3">Points either arm reaches.</param>
/// <param name="SharedCm3">Points both arms reach.</param>
/// <param name="VoxelMm">Voxel size of the common grid and cell size of the arm's cylindrical occupancy, mm.</param>
/// <param name="ArmCylindricalCm3">The arm's volume integrated exactly over its cylindrical cells (a cross-check of <paramref name="ArmCm3"/>).</param>
/// <param name="Samples">Tool-tip positions evaluated for the arm model.</param>
public sealed record WorkspaceGridVolumes(
    double ArmCm3,
    double UnionCm3,
    double SharedCm3,
    double VoxelMm,
    double ArmCylindricalCm3,
    long Samples);
