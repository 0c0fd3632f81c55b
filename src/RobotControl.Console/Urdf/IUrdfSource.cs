using RobotControl.Hardware.Model;

namespace RobotControl.WebConsole.Urdf;

/// <summary>Where the 3D view's arm model comes from: a URDF document of one arm of a robot.</summary>
public interface IUrdfSource
{
    /// <summary>The URDF of one (right-handed, unmirrored) arm of <paramref name="robot"/>, lengths in metres.</summary>
    UrdfDocument For(RobotDefinition robot);
}

/// <summary>A URDF document and the names of its movable joints in the robot's joint order.</summary>
/// <param name="Xml">The URDF text.</param>
/// <param name="JointNames">Movable joint names, one per robot joint, in the robot file's joint order.</param>
public sealed record UrdfDocument(string Xml, IReadOnlyList<string> JointNames);
