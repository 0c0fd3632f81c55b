using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Geometry;

namespace RobotControl.Analysis.Workspace;

/// <summary>
/// Per-arm, union and shared workspace volumes. The arm model's reachable region comes from
/// <see cref="ArmWorkspaceSampler"/>; each arm places it in the base frame (a mirrored arm reflects it in the plane
/// through the origin with the file's mirror-plane normal, then every arm adds its base offset). The voxel centres
/// of one common grid (cube voxels of the same size h) are tested against every arm: the arm volume counts the first
/// arm's hits, the union any arm's and the shared volume every arm's, so union = arm + arm - shared exactly.
/// <para>
/// Marking every cell a sample falls in over-covers the boundary by about half a cell, so the volume at cell size h
/// is V(h) ≈ V + c·h (measured: see docs/perf/analysis.md). <see cref="Compute"/> therefore evaluates h and 2h and
/// reports the Richardson extrapolation 2·V(h) − V(2h), with both raw results alongside.
/// </para>
/// </summary>
public static class WorkspaceCalculator
{
    /// <summary>The default (finer) cell size, mm.</summary>
    public const double DefaultVoxelMm = 2.0;

    /// <summary>Volumes at cell sizes h and 2h, extrapolated to h → 0.</summary>
    public static WorkspaceVolumes Compute(RobotDefinition robot, double voxelMm = DefaultVoxelMm)
    {
        ArgumentNullException.ThrowIfNull(robot);
        var fine = ComputeAt(robot, voxelMm);
        var coarse = ComputeAt(robot, 2 * voxelMm);
        return new WorkspaceVolumes(
            Extrapolate(fine.ArmCm3, coarse.ArmCm3),
            Extrapolate(fine.UnionCm3, coarse.UnionCm3),
            Extrapolate(fine.SharedCm3, coarse.SharedCm3),
            fine,
            coarse);
    }

    /// <summary>Volumes at one cell (and voxel) size <paramref name="voxelMm"/>, without extrapolation.</summary>
    public static WorkspaceGridVolumes ComputeAt(RobotDefinition robot, double voxelMm)
    {
        ArgumentNullException.ThrowIfNull(robot);
        var model = ArmWorkspaceSampler.Sample(robot, voxelMm, out var samples);
        var arms = robot.Arms.Count > 0 ? robot.Arms : [new ArmPlacement("right", false, default)];
        var placements = arms.Select(a => new Placement(a, robot.MirrorPlaneNormal)).ToArray();

        var min = new Vector3d(double.PositiveInfinity, double.PositiveInfinity, double.PositiveInfinity);
        var max = -min;
        foreach (var p in placements)
        {
            var centre = p.ToBase(model.Origin);
            var r = new Vector3d(model.RadiusMm + voxelMm, model.RadiusMm + voxelMm, model.RadiusMm + voxelMm);
            min = Min(min, centre - r);
            max = Max(max, centre + r);
        }

        var nx = (int)Math.Ceiling((max.X - min.X) / voxelMm);
        var ny = (int)Math.Ceiling((max.Y - min.Y) / voxelMm);
        var nz = (int)Math.Ceiling((max.Z - min.Z) / voxelMm);
        long armHits = 0, unionHits = 0, sharedHits = 0;
        Parallel.For(0, nx, () => new long[3], (ix, _, counts) =>
        {
            var x = min.X + ((ix + 0.5) * voxelMm);
            for (var iy = 0; iy < ny; iy++)
            {
                var y = min.Y + ((iy + 0.5) * voxelMm);
                for (var iz = 0; iz < nz; iz++)
                {
                    var point = new Vector3d(x, y, min.Z + ((iz + 0.5) * voxelMm));
                    var any = false;
                    var all = true;
                    for (var a = 0; a < placements.Length; a++)
                    {
                        var inside = model.Contains(placements[a].ToModel(point));
                        counts[0] += a == 0 && inside ? 1 : 0;
                        any |= inside;
                        all &= inside;
                    }

                    counts[1] += any ? 1 : 0;
                    counts[2] += all ? 1 : 0;
                }
            }

            return counts;
        }, counts =>
        {
            Interlocked.Add(ref armHits, counts[0]);
            Interlocked.Add(ref unionHits, counts[1]);
            Interlocked.Add(ref sharedHits, counts[2]);
        });

        var voxelCm3 = voxelMm * voxelMm * voxelMm / 1000.0;
        return new WorkspaceGridVolumes(
            armHits * voxelCm3,
            unionHits * voxelCm3,
            sharedHits * voxelCm3,
            voxelMm,
            model.VolumeMm3() / 1000.0,
            samples);
    }

    private static double Extrapolate(double fine, double coarse) => (2 * fine) - coarse;

    private static Vector3d Min(Vector3d a, Vector3d b) => new(Math.Min(a.X, b.X), Math.Min(a.Y, b.Y), Math.Min(a.Z, b.Z));

    private static Vector3d Max(Vector3d a, Vector3d b) => new(Math.Max(a.X, b.X), Math.Max(a.Y, b.Y), Math.Max(a.Z, b.Z));

    /// <summary>Base frame = offset + M · model frame, M the reflection in the mirror plane (or identity).</summary>
    private readonly struct Placement
    {
        private readonly Vector3d _offset;
        private readonly Vector3d _normal;
        private readonly bool _mirrored;

        public Placement(ArmPlacement arm, Vector3Data mirrorNormal)
        {
            _offset = new Vector3d(arm.BaseOffsetMm.X, arm.BaseOffsetMm.Y, arm.BaseOffsetMm.Z);
            _normal = new Vector3d(mirrorNormal.X, mirrorNormal.Y, mirrorNormal.Z).Normalized();
            _mirrored = arm.Mirrored;
            if (_mirrored && _normal.LengthSquared == 0)
            {
                throw new ArgumentException($"arm '{arm.Name}' is mirrored but the robot's mirror-plane normal is zero");
            }
        }

        public Vector3d ToBase(Vector3d model) => _offset + Reflect(model);

        // A reflection is its own inverse.
        public Vector3d ToModel(Vector3d point) => Reflect(point - _offset);

        private Vector3d Reflect(Vector3d p) => _mirrored ? p - (_normal * (2 * Vector3d.Dot(_normal, p))) : p;
    }
}
