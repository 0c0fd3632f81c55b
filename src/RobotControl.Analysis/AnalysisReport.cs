using RobotControl.Analysis.CurrentLimits;
using RobotControl.Analysis.Drivetrain;
using RobotControl.Analysis.Sweep;
using RobotControl.Analysis.Workspace;
using RobotControl.Definitions.Model;

namespace RobotControl.Analysis;

/// <summary>Everything one capability analysis produced.</summary>
/// <param name="Robot">The analysed robot.</param>
/// <param name="Drivetrain">Output torque and speed of every actuator in file order.</param>
/// <param name="Sweep">Per-point sweep results.</param>
/// <param name="Requirements">Requirement fractions by the reference method.</param>
/// <param name="CouplingAwareRequirements">Requirement fractions by the coupling-aware method, when computed.</param>
/// <param name="CouplingAwareActuators">Actuators whose limits the coupling-aware method used, in its column order.</param>
/// <param name="GrasperRoll">The tool-roll speed requirement and what the tool-roll drive gives, or null when the robot has no tool-roll drive.</param>
/// <param name="Workspace">Workspace volumes, when computed.</param>
/// <param name="CurrentLimits">Gearhead-protecting current limits per actuator in file order.</param>
public sealed record AnalysisReport(
    RobotDefinition Robot,
    IReadOnlyList<DrivetrainPerformance> Drivetrain,
    SweepResult Sweep,
    RequirementReport Requirements,
    RequirementReport? CouplingAwareRequirements,
    IReadOnlyList<string>? CouplingAwareActuators,
    GrasperRollCheck? GrasperRoll,
    WorkspaceVolumes? Workspace,
    IReadOnlyList<CurrentLimit> CurrentLimits);

/// <summary>The grasper-roll speed requirement against the tool-roll drive.</summary>
/// <param name="Joint">The tool-roll joint (the chain's last joint).</param>
/// <param name="RequiredRadPerS">Required roll speed, rad/s.</param>
/// <param name="AvailableRadPerS">The drive's output speed, rad/s.</param>
public sealed record GrasperRollCheck(string Joint, double RequiredRadPerS, double AvailableRadPerS)
{
    /// <summary>True when the drive reaches the requirement.</summary>
    public bool Met => AvailableRadPerS >= RequiredRadPerS;
}
