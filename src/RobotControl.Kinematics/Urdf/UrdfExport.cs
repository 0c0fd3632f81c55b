using System.Globalization;
using System.Xml;
using System.Xml.Linq;
using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Urdf;

/// <summary>
/// Writes a robot file as URDF (metres, radians): both arms as the file places them on a common <c>body</c> link,
/// joints named <c>{arm}_{joint}</c> from the file's joint names, limits from the joint ranges, effort and velocity
/// from the drivetrains and the modules' speed limits, and simple cylinders sized from the link lengths. For
/// CoppeliaSim's URDF importer, RViz and the console's 3D view. See <see cref="UrdfRobotBuilder"/> for the frames.
/// </summary>
public static class UrdfExport
{
    /// <summary>Metres in a millimetre (URDF and the 3D tools work in metres; the robot files in mm).</summary>
    public const double MetresPerMm = 0.001;

    /// <summary>The URDF joint name of joint <paramref name="jointName"/> of arm <paramref name="armName"/>.</summary>
    public static string JointName(string armName, string jointName) => $"{armName}_{jointName}";

    /// <summary>The URDF link at the tool tip of arm <paramref name="armName"/>.</summary>
    public static string ToolLinkName(string armName) => $"{armName}_tool";

    /// <summary>The URDF document of <paramref name="robot"/>.</summary>
    public static XDocument ToDocument(RobotDefinition robot)
    {
        ArgumentNullException.ThrowIfNull(robot);
        var (links, joints) = UrdfRobotBuilder.Build(robot);
        var root = new XElement("robot", new XAttribute("name", robot.Name));
        root.Add(new XComment($" Written by robotctl urdf from {Path.GetFileName(robot.SourceFile)}; lengths in metres, angles in radians. "));
        root.Add(new XElement("material", new XAttribute("name", "link"), new XElement("color", new XAttribute("rgba", "0.7 0.7 0.75 1"))));
        foreach (var link in links)
        {
            root.Add(Link(link));
        }

        foreach (var joint in joints)
        {
            root.Add(Joint(joint));
        }

        return new XDocument(new XDeclaration("1.0", "utf-8", null), root);
    }

    /// <summary>Writes the URDF of <paramref name="robot"/> to <paramref name="writer"/> (declared UTF-8, as files and standard output carry it).</summary>
    public static void Write(RobotDefinition robot, TextWriter writer)
    {
        ArgumentNullException.ThrowIfNull(writer);

        // An XmlWriter declares the TextWriter's encoding (UTF-16 for a StringWriter); the text is written out as UTF-8.
        writer.WriteLine("<?xml version=\"1.0\" encoding=\"utf-8\"?>");
        var settings = new XmlWriterSettings { Indent = true, IndentChars = "  ", OmitXmlDeclaration = true };
        using (var xml = XmlWriter.Create(writer, settings))
        {
            ToDocument(robot).Save(xml);
        }

        writer.WriteLine();
    }

    private static XElement Link(UrdfLink link)
    {
        var element = new XElement("link", new XAttribute("name", link.Name));
        if (link.Visual is { } frame)
        {
            var geometry = link.LengthMm > 0
                ? new XElement("cylinder", new XAttribute("radius", Number(link.RadiusMm * MetresPerMm)), new XAttribute("length", Number(link.LengthMm * MetresPerMm)))
                : new XElement("sphere", new XAttribute("radius", Number(link.RadiusMm * MetresPerMm)));
            element.Add(new XElement(
                "visual",
                Origin(frame),
                new XElement("geometry", geometry),
                new XElement("material", new XAttribute("name", "link"))));
        }

        return element;
    }

    private static XElement Joint(UrdfJoint joint)
    {
        var element = new XElement(
            "joint",
            new XAttribute("name", joint.Name),
            new XAttribute("type", joint.IsRevolute ? "revolute" : "fixed"),
            new XElement("parent", new XAttribute("link", joint.Parent)),
            new XElement("child", new XAttribute("link", joint.Child)),
            Origin(joint.Origin));
        if (joint.Limits is { } limits)
        {
            element.Add(new XElement("axis", new XAttribute("xyz", Vector(joint.Axis, 1))));
            if (limits.EffortNm is null || limits.VelocityRadS is null)
            {
                element.Add(new XComment(" the robot file gives no drivetrain or no module speed limit for this joint: 0 written for what is missing "));
            }

            element.Add(new XElement(
                "limit",
                new XAttribute("lower", Number(limits.LowerRad)),
                new XAttribute("upper", Number(limits.UpperRad)),
                new XAttribute("effort", Number(limits.EffortNm ?? 0)),
                new XAttribute("velocity", Number(limits.VelocityRadS ?? 0))));
        }

        return element;
    }

    private static XElement Origin(UrdfFrame frame)
    {
        var (roll, pitch, yaw) = frame.RollPitchYaw();
        return new XElement(
            "origin",
            new XAttribute("xyz", Vector(frame.Position, MetresPerMm)),
            new XAttribute("rpy", Vector(new Vector3d(roll, pitch, yaw), 1)));
    }

    private static string Vector(Vector3d v, double scale) =>
        $"{Number(v.X * scale)} {Number(v.Y * scale)} {Number(v.Z * scale)}";

    // 15 significant digits round-trip what the robot files hold; -0 and rounding dust print as 0.
    private static string Number(double value) =>
        Math.Abs(value) < 1e-15 ? "0" : value.ToString("G15", CultureInfo.InvariantCulture);
}
