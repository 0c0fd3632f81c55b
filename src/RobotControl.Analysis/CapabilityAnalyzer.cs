using System.Diagnostics;
using RobotControl.Analysis.CurrentLimits;
using RobotControl.Analysis.Drivetrain;
using RobotControl.Analysis.Sweep;
using RobotControl.Analysis.Workspace;
using RobotControl.Definitions.Model;

namespace RobotControl.Analysis;

/// <summary>
/// Runs a capability analysis of one robot (docs/algorithms.md, capability analysis): drivetrain figures,
/// the two-joint sweep (manipulability, velocity, force; reference method and optionally coupling-aware),
/// requirement fractions, workspace volumes and current limits.
/// </summary>
public static class CapabilityAnalyzer
{
    /// <summary>Runs the analysis. Nothing is written; see <see cref="Output.AnalysisOutputWriter"/>.</summary>
    /// <exception cref="ArgumentException">The options do not fit the robot (e.g. a used joint without a drive).</exception>
    public static AnalysisReport Run(RobotDefinition robot, AnalysisOptions options, IProgress<AnalysisProgress>? progress = null)
    {
        ArgumentNullException.ThrowIfNull(robot);
        ArgumentNullException.ThrowIfNull(options);
        var spec = options.Sweep ?? SweepSpecification.FromCrossSection(robot.CrossSection);
        var clock = Stopwatch.StartNew();

        var drivetrain = DrivetrainCalculator.EvaluateAll(robot);
        var limits = JointDriveLimits.FromRobot(robot, drivetrain);
        var coupled = options.CouplingAware ? CoupledDriveModel.Create(robot, spec.JointsUsed, drivetrain) : null;
        progress?.Report(new AnalysisProgress("sweep", 0.0, null));
        var sweep = CapabilitySweep.Run(robot, spec, limits, coupled);
        var requirements = RequirementReport.Evaluate(sweep.Reference, robot.Requirements);
        var coupledRequirements = sweep.CouplingAware is null ? null : RequirementReport.Evaluate(sweep.CouplingAware, robot.Requirements);
        progress?.Report(new AnalysisProgress("sweep", options.Workspace ? 0.1 : 0.9, clock.Elapsed));

        WorkspaceVolumes? workspace = null;
        if (options.Workspace)
        {
            clock.Restart();
            progress?.Report(new AnalysisProgress("workspace volumes", 0.1, null));
            workspace = WorkspaceCalculator.Compute(robot, options.WorkspaceVoxelMm);
            progress?.Report(new AnalysisProgress("workspace volumes", 0.9, clock.Elapsed));
        }

        var currentLimits = CurrentLimitCalculator.EvaluateAll(robot);
        return new AnalysisReport(
            robot,
            drivetrain,
            sweep,
            requirements,
            coupledRequirements,
            coupled?.ActuatorNames,
            GrasperRoll(robot, drivetrain),
            workspace,
            currentLimits);
    }

    // The tool roll is the chain's last joint (both robot files end with it); its drive's output speed is compared
    // with the grasper-roll requirement.
    private static GrasperRollCheck? GrasperRoll(RobotDefinition robot, IReadOnlyList<DrivetrainPerformance> drivetrain)
    {
        var last = robot.JointCount - 1;
        for (var k = 0; k < robot.Actuators.Count; k++)
        {
            if (robot.Actuators[k].JointIndex == last && !robot.PositionJoints.Contains(last))
            {
                return new GrasperRollCheck(robot.Joints[last].Name, robot.Requirements.GrasperRollRadPerS, drivetrain[k].SpeedRadPerS);
            }
        }

        return null;
    }
}
