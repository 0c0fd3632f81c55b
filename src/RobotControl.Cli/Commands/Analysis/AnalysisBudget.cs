using System.Globalization;
using RobotControl.Analysis.Sweep;
using RobotControl.Definitions.Model;

namespace RobotControl.Cli.Commands.Analysis;

/// <summary>
/// The work <c>robotctl analyze</c> accepts, estimated before it starts: sweep grid points (from the range and the
/// step) and workspace cells (from a bound on the arm's reach and the voxel size, the finer of the two grids the
/// volumes are extrapolated from). Beyond the limits the command refuses with the estimate and the nearest setting
/// that fits, instead of running out of memory or integer range hours later.
/// </summary>
internal static class AnalysisBudget
{
    /// <summary>Most sweep grid points (the reference cross-sections have a few thousand).</summary>
    public const double MaxSweepPoints = 4e6;

    /// <summary>Most workspace cells of the finer grid (2 mm on the LB robot is a few million).</summary>
    public const double MaxWorkspaceCells = 4e8;

    /// <summary>Why the analysis is too large, or null when it fits.</summary>
    public static string? Check(RobotDefinition robot, SweepSpecification sweep, bool workspace, double voxelMm)
    {
        ArgumentNullException.ThrowIfNull(robot);
        ArgumentNullException.ThrowIfNull(sweep);
        var c = CultureInfo.InvariantCulture;
        var points = Points(sweep.XMinRad, sweep.XMaxRad, sweep.StepRad) * Points(sweep.YMinRad, sweep.YMaxRad, sweep.StepRad);
        if (points > MaxSweepPoints)
        {
            var step = sweep.StepRad * Math.Sqrt(points / MaxSweepPoints) * 180 / Math.PI;
            return string.Create(c, $"the sweep would have {points:G3} grid points (limit {MaxSweepPoints:G3}): use a step of at least {step:G3} deg");
        }

        if (workspace)
        {
            var cells = WorkspaceCells(robot, voxelMm);
            if (cells > MaxWorkspaceCells)
            {
                var h = voxelMm * Math.Cbrt(cells / MaxWorkspaceCells);
                return string.Create(c, $"--voxel-mm {voxelMm:G3}: the workspace grid would have {cells:G3} cells (limit {MaxWorkspaceCells:G3}): use --voxel-mm {h:G3} or more, or --no-workspace");
            }
        }

        return null;
    }

    /// <summary>Cells of a cube around every arm's reach bound (the sum of the DH lengths) at cell size <paramref name="voxelMm"/>.</summary>
    internal static double WorkspaceCells(RobotDefinition robot, double voxelMm)
    {
        var reach = robot.Dh.Sum(r => Math.Abs(r.AMm) + Math.Abs(r.DMm));
        var arms = Math.Max(1, robot.Arms.Count);
        var side = ((2 * reach) + (2 * voxelMm)) / voxelMm;
        return arms * side * side * side;
    }

    private static double Points(double min, double max, double step) => Math.Floor((max - min) / step) + 1;
}
