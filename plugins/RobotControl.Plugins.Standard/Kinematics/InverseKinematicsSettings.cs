using System.Globalization;
using RobotControl.Definitions.Json;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Standard.Kinematics;

/// <summary>Which orientation axes of the target the IK honours.</summary>
public enum OrientationMode
{
    /// <summary>Position only.</summary>
    None,

    /// <summary>The tool axis (z) only, e.g. the wrist-roll choice of a 4-DOF arm.</summary>
    ToolAxis,

    /// <summary>Full orientation.</summary>
    Full,
}

/// <summary>Settings of <see cref="InverseKinematicsPlugin"/> (the solver's options plus the start pose).</summary>
public sealed record InverseKinematicsSettings : PluginSettings
{
    /// <summary>Which orientation axes to honour.</summary>
    [Setting("Orientation axes the solution must match: none (position only), tool_axis, or full.")]
    public OrientationMode Orientation { get; init; } = OrientationMode.None;

    /// <summary>Joint angles to start from (comma-separated, degrees, one per joint); empty: mid-range.</summary>
    [Setting("Joint angles the first solve starts from (comma-separated, one per joint); empty for mid-range. Later solves start from the previous solution.", Units = "deg")]
    public string InitialJointsDeg { get; init; } = "";

    /// <summary>Position tolerance.</summary>
    [Setting("Position tolerance of a solve.", Units = "mm", Minimum = 1e-6, Maximum = 10)]
    public double PositionToleranceMm { get; init; } = 0.01;

    /// <summary>Bound on work per solve (keeps the tick's time bounded).</summary>
    [Setting("Upper bound on iterations per solve (bounds the tick's time).", Minimum = 1, Maximum = 100000)]
    public int MaxIterations { get; init; } = 200;

    /// <summary>Restarts per solve; 0 keeps the solution continuous while tracking.</summary>
    [Setting("Restarts allowed when a solve stalls (hops along a singular pose, then fixed seeds nearest the target); 0 keeps tracking continuous (a restart may jump to another branch).", Minimum = 0, Maximum = 100)]
    public int MaxRestarts { get; init; }

    /// <summary>Workspace spring stiffness k_s.</summary>
    [Setting("Workspace spring k_s: force output per mm between the demanded and the reachable point.", Units = "N/mm", Minimum = 0, Maximum = 10)]
    public double WorkspaceStiffnessNPerMm { get; init; } = 0.05;

    /// <summary>Parses <see cref="InitialJointsDeg"/>; null when empty.</summary>
    public double[]? ParseInitialJointsDeg()
    {
        if (string.IsNullOrWhiteSpace(InitialJointsDeg))
        {
            return null;
        }

        return [.. InitialJointsDeg.Split(',').Select(s => double.Parse(s.Trim(), NumberStyles.Float, CultureInfo.InvariantCulture))];
    }

    /// <inheritdoc />
    public override IEnumerable<JsonProblem> CheckConsistency()
    {
        if (string.IsNullOrWhiteSpace(InitialJointsDeg))
        {
            yield break;
        }

        foreach (var part in InitialJointsDeg.Split(','))
        {
            if (!double.TryParse(part.Trim(), NumberStyles.Float, CultureInfo.InvariantCulture, out var v) || !double.IsFinite(v))
            {
                yield return new JsonProblem("initial_joints_deg", $"'{part.Trim()}' is not a number (expected comma-separated degrees)");
                yield break;
            }
        }
    }
}
