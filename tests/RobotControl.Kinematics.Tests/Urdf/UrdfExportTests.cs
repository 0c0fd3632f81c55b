using System.Diagnostics;
using System.Globalization;
using System.Xml.Linq;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Mirroring;
using RobotControl.Kinematics.Urdf;

namespace RobotControl.Kinematics.Tests.Urdf;

public sealed class UrdfExportTests
{
    [Theory]
    [MemberData(nameof(TestRobots.Names), MemberType = typeof(TestRobots))]
    public void Urdf_forward_kinematics_match_the_project_fk_for_both_arms(string file)
    {
        var robot = TestRobots.ByFile(file);
        var urdf = UrdfExport.ToDocument(robot);
        var chain = new KinematicChain(robot);
        var state = chain.CreateState();
        var random = new Random(15);
        var q = new double[chain.JointCount];
        for (var sample = 0; sample < 50; sample++)
        {
            if (sample > 0)
            {
                TestRobots.FillRandomJoints(chain, random, q);
            }

            state.Update(q);
            foreach (var arm in robot.Arms)
            {
                var values = new Dictionary<string, double>();
                for (var j = 0; j < q.Length; j++)
                {
                    values[$"{arm.Name}_{robot.Joints[j].Name}"] = q[j];
                }

                var (rotation, position) = ComposeToLink(urdf, $"{arm.Name}_tool", values);
                var expected = new ArmMirror(robot, arm.Name).ModelToBody(state.ToolPose);
                Assert.Equal(expected.Position.X, position[0] * 1000, 6);
                Assert.Equal(expected.Position.Y, position[1] * 1000, 6);
                Assert.Equal(expected.Position.Z, position[2] * 1000, 6);
                for (var r = 0; r < 3; r++)
                {
                    for (var c = 0; c < 3; c++)
                    {
                        Assert.Equal(expected.Rotation.At(r, c), rotation[r, c], 9);
                    }
                }
            }
        }
    }

    [Theory]
    [MemberData(nameof(TestRobots.Names), MemberType = typeof(TestRobots))]
    public void Urdf_has_one_revolute_joint_per_arm_joint_with_the_files_limits(string file)
    {
        var robot = TestRobots.ByFile(file);
        var urdf = UrdfExport.ToDocument(robot);
        var revolute = urdf.Root!.Elements("joint").Where(j => (string?)j.Attribute("type") == "revolute").ToList();
        Assert.Equal(robot.Arms.Count * robot.JointCount, revolute.Count);
        foreach (var arm in robot.Arms)
        {
            foreach (var joint in robot.Joints)
            {
                var element = revolute.Single(j => (string?)j.Attribute("name") == $"{arm.Name}_{joint.Name}");
                var limit = element.Element("limit")!;
                Assert.Equal(joint.MinRad, Number(limit, "lower"), 12);
                Assert.Equal(joint.MaxRad, Number(limit, "upper"), 12);
                Assert.True(Number(limit, "effort") > 0, $"{arm.Name}_{joint.Name}: effort from the drivetrain");
                Assert.True(Number(limit, "velocity") > 0, $"{arm.Name}_{joint.Name}: velocity from the module's speed limit");
            }
        }
    }

    [Theory]
    [MemberData(nameof(TestRobots.Names), MemberType = typeof(TestRobots))]
    public void Check_urdf_accepts_the_file(string file)
    {
        var robot = TestRobots.ByFile(file);
        var path = Path.Combine(Path.GetTempPath(), $"robotcontrol-urdf-{Environment.ProcessId}-{file}.urdf");
        using (var writer = new StreamWriter(path))
        {
            UrdfExport.Write(robot, writer);
        }

        try
        {
            var start = new ProcessStartInfo("check_urdf", [path]) { RedirectStandardOutput = true, RedirectStandardError = true };
            Process process;
            try
            {
                process = Process.Start(start)!;
            }
            catch (System.ComponentModel.Win32Exception)
            {
                Assert.Fail("check_urdf is not installed: run tools/bootstrap.sh (Debian package liburdfdom-tools)");
                return;
            }

            using (process)
            {
                var stdout = process.StandardOutput.ReadToEnd();
                var stderr = process.StandardError.ReadToEnd();
                process.WaitForExit();
                Assert.True(process.ExitCode == 0, stdout + stderr);
                Assert.Contains("Successfully Parsed XML", stdout, StringComparison.Ordinal);
                Assert.Contains("root Link: body has 2 child(ren)", stdout, StringComparison.Ordinal);
            }
        }
        finally
        {
            File.Delete(path);
        }
    }

    /// <summary>
    /// Walks the URDF from the root to <paramref name="link"/> and composes origin (xyz, rpy) and axis turns, with
    /// plain 3 x 3 arrays: nothing of the project's kinematics code.
    /// </summary>
    private static (double[,] Rotation, double[] Position) ComposeToLink(XDocument urdf, string link, Dictionary<string, double> values)
    {
        var joints = urdf.Root!.Elements("joint").ToDictionary(j => (string)j.Element("child")!.Attribute("link")!);
        var path = new List<XElement>();
        for (var current = link; joints.TryGetValue(current, out var joint); current = (string)joint.Element("parent")!.Attribute("link")!)
        {
            path.Insert(0, joint);
        }

        var r = Identity();
        var p = new double[3];
        foreach (var joint in path)
        {
            var origin = joint.Element("origin")!;
            var xyz = Triple(origin, "xyz");
            var rpy = Triple(origin, "rpy");
            var rp = Apply(r, xyz);
            p = [p[0] + rp[0], p[1] + rp[1], p[2] + rp[2]];
            r = Multiply(r, Multiply(AxisAngle([0, 0, 1], rpy[2]), Multiply(AxisAngle([0, 1, 0], rpy[1]), AxisAngle([1, 0, 0], rpy[0]))));
            if ((string?)joint.Attribute("type") == "revolute")
            {
                r = Multiply(r, AxisAngle(Triple(joint.Element("axis")!, "xyz"), values[(string)joint.Attribute("name")!]));
            }
        }

        return (r, p);
    }

    private static double Number(XElement element, string attribute) =>
        double.Parse((string)element.Attribute(attribute)!, CultureInfo.InvariantCulture);

    private static double[] Triple(XElement element, string attribute) =>
        ((string)element.Attribute(attribute)!).Split(' ').Select(s => double.Parse(s, CultureInfo.InvariantCulture)).ToArray();

    private static double[,] Identity() => new double[,] { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };

    // Rodrigues: R = I + sin(t) K + (1 - cos(t)) K², K the cross-product matrix of the unit axis.
    private static double[,] AxisAngle(double[] axis, double angle)
    {
        var n = Math.Sqrt((axis[0] * axis[0]) + (axis[1] * axis[1]) + (axis[2] * axis[2]));
        var (x, y, z) = (axis[0] / n, axis[1] / n, axis[2] / n);
        var k = new double[,] { { 0, -z, y }, { z, 0, -x }, { -y, x, 0 } };
        var k2 = Multiply(k, k);
        var r = Identity();
        for (var i = 0; i < 3; i++)
        {
            for (var j = 0; j < 3; j++)
            {
                r[i, j] += (Math.Sin(angle) * k[i, j]) + ((1 - Math.Cos(angle)) * k2[i, j]);
            }
        }

        return r;
    }

    private static double[,] Multiply(double[,] a, double[,] b)
    {
        var c = new double[3, 3];
        for (var i = 0; i < 3; i++)
        {
            for (var j = 0; j < 3; j++)
            {
                for (var k = 0; k < 3; k++)
                {
                    c[i, j] += a[i, k] * b[k, j];
                }
            }
        }

        return c;
    }

    private static double[] Apply(double[,] r, double[] v) =>
    [
        (r[0, 0] * v[0]) + (r[0, 1] * v[1]) + (r[0, 2] * v[2]),
        (r[1, 0] * v[0]) + (r[1, 1] * v[1]) + (r[1, 2] * v[2]),
        (r[2, 0] * v[0]) + (r[2, 1] * v[1]) + (r[2, 2] * v[2]),
    ];
}
