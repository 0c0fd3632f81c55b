using RobotControl.Definitions.Json;
using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Urdf;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.CoppeliaSim;

/// <summary>
/// The scene path of every joint of every arm, arm-major (the order of the plug-in's ports): by default
/// <c>{model}/{arm}_{joint}</c>, the joint names <c>robotctl urdf</c> writes; <c>joint_paths</c> overrides single joints.
/// </summary>
internal static class JointPathMap
{
    /// <summary>Signal names (<c>arm.joint</c>) and scene paths, arm-major.</summary>
    /// <exception cref="SettingsException">An override names no joint of the robot or is malformed.</exception>
    public static IReadOnlyList<(string Signal, string Path)> Build(RobotDefinition robot, CoppeliaSimSettings settings, string instanceName)
    {
        ArgumentNullException.ThrowIfNull(robot);
        ArgumentNullException.ThrowIfNull(settings);
        var model = settings.Model.TrimEnd('/');
        var map = new List<(string Signal, string Path)>();
        foreach (var arm in robot.Arms)
        {
            foreach (var joint in robot.Joints)
            {
                map.Add(($"{arm.Name}.{joint.Name}", $"{model}/{UrdfExport.JointName(arm.Name, joint.Name)}"));
            }
        }

        foreach (var (signal, path) in ParseOverrides(settings.JointPaths, instanceName))
        {
            var index = map.FindIndex(m => m.Signal == signal);
            if (index < 0)
            {
                throw Error(instanceName, $"'{signal}' is not a joint of {robot.Name} (joints: {string.Join(", ", map.Select(m => m.Signal))})");
            }

            map[index] = (signal, path);
        }

        if (map.Count > JointFrame.Capacity)
        {
            throw Error(instanceName, $"{robot.Name} has {map.Count} joints over all arms; the bridge carries at most {JointFrame.Capacity}");
        }

        return map;
    }

    /// <summary>The <c>arm.joint=/path</c> pairs of the setting.</summary>
    public static IEnumerable<(string Signal, string Path)> ParseOverrides(string text, string instanceName)
    {
        foreach (var item in (text ?? "").Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))
        {
            var equals = item.IndexOf('=', StringComparison.Ordinal);
            var signal = equals > 0 ? item[..equals].Trim() : "";
            var path = equals > 0 ? item[(equals + 1)..].Trim() : "";
            if (signal.Length == 0 || path.Length == 0)
            {
                throw Error(instanceName, $"'{item}' is not arm.joint=/path");
            }

            yield return (signal, path);
        }
    }

    private static SettingsException Error(string instanceName, string message) =>
        new(instanceName, [new JsonProblem("joint_paths", message)]);
}
