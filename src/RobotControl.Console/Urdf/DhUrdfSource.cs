using System.Globalization;
using System.Xml.Linq;
using RobotControl.Hardware.Model;

namespace RobotControl.WebConsole.Urdf;

/// <summary>
/// Builds an arm's URDF from the robot file's standard DH table. Each row T = Rz(theta) Tz(d) Tx(a) Rx(alpha) with
/// theta = q + offset becomes a revolute joint about z (its origin turned by the offset) into a link that draws the
/// row's offset (a, 0, d) as a rod, then a fixed joint (a, 0, d), roll alpha into the next row's frame. Fixed rows
/// become fixed joints. Lengths in metres.
/// </summary>
public sealed class DhUrdfSource : IUrdfSource
{
    private const double RodRadiusM = 0.003;
    private const double JointRadiusM = 0.005;

    /// <inheritdoc />
    public UrdfDocument For(RobotDefinition robot)
    {
        ArgumentNullException.ThrowIfNull(robot);
        var root = new XElement("robot", new XAttribute("name", robot.Name));
        root.Add(Material("rod", "0.75 0.78 0.82 1"), Material("joint", "0.2 0.45 0.85 1"));
        var parent = "base";
        root.Add(new XElement("link", new XAttribute("name", parent), Sphere(JointRadiusM * 1.6, "joint")));
        var jointNames = new string?[robot.JointCount];
        for (var i = 0; i < robot.Dh.Count; i++)
        {
            var row = robot.Dh[i];
            var link = $"link{i + 1}";
            var name = row.IsFixed ? $"fixed{i + 1}" : (jointNames[row.JointIndex] is null ? robot.Joints[row.JointIndex].Name : $"{robot.Joints[row.JointIndex].Name}_{i + 1}");
            var joint = new XElement(
                "joint",
                new XAttribute("name", name),
                new XAttribute("type", row.IsFixed ? "fixed" : "revolute"),
                Origin(0, 0, 0, 0, 0, row.ThetaOffsetRad),
                new XElement("parent", new XAttribute("link", parent)),
                new XElement("child", new XAttribute("link", link)));
            if (!row.IsFixed)
            {
                var j = robot.Joints[row.JointIndex];
                joint.Add(new XElement("axis", new XAttribute("xyz", "0 0 1")));
                joint.Add(new XElement(
                    "limit",
                    new XAttribute("lower", F(j.MinRad)),
                    new XAttribute("upper", F(j.MaxRad)),
                    new XAttribute("effort", "1"),
                    new XAttribute("velocity", "1")));
                jointNames[row.JointIndex] ??= name;
            }

            var a = row.AMm / 1000;
            var d = row.DMm / 1000;
            var linkElement = new XElement("link", new XAttribute("name", link), Sphere(JointRadiusM, "joint"));
            var length = Math.Sqrt((a * a) + (d * d));
            if (length > 1e-6)
            {
                linkElement.Add(new XElement(
                    "visual",
                    Origin(a / 2, 0, d / 2, 0, Math.Atan2(a, d), 0),
                    new XElement("geometry", new XElement("cylinder", new XAttribute("radius", F(RodRadiusM)), new XAttribute("length", F(length)))),
                    new XElement("material", new XAttribute("name", "rod"))));
            }

            var frame = $"frame{i + 1}";
            root.Add(joint, linkElement, new XElement("link", new XAttribute("name", frame)));
            root.Add(new XElement(
                "joint",
                new XAttribute("name", $"offset{i + 1}"),
                new XAttribute("type", "fixed"),
                Origin(a, 0, d, row.AlphaRad, 0, 0),
                new XElement("parent", new XAttribute("link", link)),
                new XElement("child", new XAttribute("link", frame))));
            parent = frame;
        }

        var missing = Enumerable.Range(0, robot.JointCount).Where(j => jointNames[j] is null).Select(j => robot.Joints[j].Name).ToList();
        if (missing.Count > 0)
        {
            throw new InvalidOperationException($"{robot.SourceFile}: no DH row moves joint(s) {string.Join(", ", missing)}");
        }

        return new UrdfDocument(new XDocument(root).ToString(), jointNames!);
    }

    private static XElement Material(string name, string rgba) =>
        new("material", new XAttribute("name", name), new XElement("color", new XAttribute("rgba", rgba)));

    private static XElement Sphere(double radius, string material) =>
        new("visual", new XElement("geometry", new XElement("sphere", new XAttribute("radius", F(radius)))), new XElement("material", new XAttribute("name", material)));

    private static XElement Origin(double x, double y, double z, double roll, double pitch, double yaw) =>
        new("origin", new XAttribute("xyz", $"{F(x)} {F(y)} {F(z)}"), new XAttribute("rpy", $"{F(roll)} {F(pitch)} {F(yaw)}"));

    private static string F(double v) => v.ToString("0.#########", CultureInfo.InvariantCulture);
}
