using System.Globalization;
using RobotControl.Definitions.Model;

namespace RobotControl.Analysis.Sweep;

/// <summary>
/// Parses the <c>--sweep</c> text: <c>x_joint:min:max,y_joint:min:max[,step=1][,fixed=joint:value]...[,used=j1+j2+j3]</c>
/// in degrees. Joints are named by name (<c>elbow</c>) or symbol (<c>phi4</c>). A bare <c>joint:value</c> item after the
/// two ranges is another fixed value. Joints not named keep the robot file's cross-section value, else 0 clamped into
/// the joint's range. <c>used</c> defaults to the robot's position joints (the reference design's choice).
/// </summary>
public static class SweepSpecificationParser
{
    private const double Deg = Math.PI / 180.0;

    /// <summary>Parses <paramref name="text"/> for <paramref name="robot"/>.</summary>
    /// <exception cref="FormatException">The text is malformed or names an unknown joint; the message says which part.</exception>
    public static SweepSpecification Parse(string text, RobotDefinition robot)
    {
        ArgumentNullException.ThrowIfNull(text);
        ArgumentNullException.ThrowIfNull(robot);
        var items = text.Split(',', StringSplitOptions.TrimEntries | StringSplitOptions.RemoveEmptyEntries);
        if (items.Length < 2)
        {
            throw new FormatException($"--sweep '{text}': expected x_joint:min:max,y_joint:min:max[,step=deg][,fixed=joint:deg]...");
        }

        var (xJoint, xMin, xMax) = ParseRange(items[0], robot);
        var (yJoint, yMin, yMax) = ParseRange(items[1], robot);
        var step = 1.0;
        var fixedValues = DefaultFixed(robot);
        IReadOnlyList<int> used = robot.PositionJoints;
        foreach (var item in items.Skip(2))
        {
            var eq = item.IndexOf('=', StringComparison.Ordinal);
            var key = eq < 0 ? "fixed" : item[..eq].Trim();
            var value = eq < 0 ? item : item[(eq + 1)..].Trim();
            switch (key)
            {
                case "step":
                    step = ParseNumber(value, item);
                    if (!(step > 0))
                    {
                        throw new FormatException($"--sweep item '{item}': the step must be positive");
                    }

                    break;
                case "fixed":
                    var parts = value.Split(':', StringSplitOptions.TrimEntries);
                    if (parts.Length != 2)
                    {
                        throw new FormatException($"--sweep item '{item}': expected fixed=joint:deg");
                    }

                    var joint = ResolveJoint(parts[0], robot, item);
                    fixedValues[joint] = ParseNumber(parts[1], item) * Deg;
                    CheckInRange(robot, joint, fixedValues[joint], item);
                    break;
                case "used":
                    used = value.Split('+', StringSplitOptions.TrimEntries).Select(j => ResolveJoint(j, robot, item)).ToArray();
                    break;
                default:
                    throw new FormatException($"--sweep item '{item}': unknown key '{key}' (step, fixed, used)");
            }
        }

        if (xJoint == yJoint)
        {
            throw new FormatException($"--sweep '{text}': the two swept joints must differ");
        }

        try
        {
            return new SweepSpecification(xJoint, xMin, xMax, yJoint, yMin, yMax, step * Deg, fixedValues, used);
        }
        catch (ArgumentException ex)
        {
            throw new FormatException($"--sweep '{text}': {ex.Message}", ex);
        }
    }

    private static double[] DefaultFixed(RobotDefinition robot)
    {
        var values = new double[robot.JointCount];
        for (var j = 0; j < values.Length; j++)
        {
            values[j] = Math.Clamp(0.0, robot.Joints[j].MinRad, robot.Joints[j].MaxRad);
        }

        var crossSection = robot.CrossSection;
        for (var j = 0; j < values.Length && j < crossSection.FixedRad.Count; j++)
        {
            if (j != crossSection.XJoint && j != crossSection.YJoint)
            {
                values[j] = crossSection.FixedRad[j];
            }
        }

        return values;
    }

    private static (int Joint, double Min, double Max) ParseRange(string item, RobotDefinition robot)
    {
        var parts = item.Split(':', StringSplitOptions.TrimEntries);
        if (parts.Length != 3)
        {
            throw new FormatException($"--sweep item '{item}': expected joint:min_deg:max_deg");
        }

        var joint = ResolveJoint(parts[0], robot, item);
        var min = ParseNumber(parts[1], item) * Deg;
        var max = ParseNumber(parts[2], item) * Deg;
        if (max < min)
        {
            throw new FormatException($"--sweep item '{item}': min must not exceed max");
        }

        CheckInRange(robot, joint, min, item);
        CheckInRange(robot, joint, max, item);
        return (joint, min, max);
    }

    private static void CheckInRange(RobotDefinition robot, int joint, double value, string item)
    {
        var def = robot.Joints[joint];
        const double tolerance = 1e-9;
        if (value < def.MinRad - tolerance || value > def.MaxRad + tolerance)
        {
            throw new FormatException(
                $"--sweep item '{item}': {def.Name} must stay within its range {def.MinRad / Deg:0.###}..{def.MaxRad / Deg:0.###} deg");
        }
    }

    private static int ResolveJoint(string name, RobotDefinition robot, string item)
    {
        for (var j = 0; j < robot.JointCount; j++)
        {
            if (string.Equals(robot.Joints[j].Name, name, StringComparison.OrdinalIgnoreCase) ||
                string.Equals(robot.Joints[j].Symbol, name, StringComparison.OrdinalIgnoreCase))
            {
                return j;
            }
        }

        throw new FormatException(
            $"--sweep item '{item}': unknown joint '{name}' (joints of {robot.Name}: {string.Join(", ", robot.Joints.Select(j => $"{j.Name}/{j.Symbol}"))})");
    }

    private static double ParseNumber(string text, string item) =>
        double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out var value) && double.IsFinite(value)
            ? value
            : throw new FormatException($"--sweep item '{item}': '{text}' is not a number");
}
