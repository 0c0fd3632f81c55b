using System.CommandLine;
using System.Globalization;
using RobotControl.Definitions.Model;
using RobotControl.Kinematics.ClosedForm;
using RobotControl.Kinematics.Coupling;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;

namespace RobotControl.Cli.Commands.Kinematics;

/// <summary>
/// <c>robotctl fk &lt;robot file&gt; --joints-deg a,b,c,...</c>: forward kinematics demo. Prints the tool pose, the
/// geometric Jacobian, the manipulability and the motor angles behind the joint vector; for a CRB-type arm also the
/// closed-form inverse of the tool position as a check. Needs nothing but the robot file and its catalogues.
/// </summary>
internal sealed class FkCommand : ICliCommand
{
    private const double Deg = Math.PI / 180;

    /// <inheritdoc />
    public Command Build()
    {
        var robotArgument = new Argument<FileInfo>("robot") { Description = "Robot data file, e.g. hardware/robots/lb-1.0.json" };
        var jointsOption = new Option<string>("--joints-deg")
        {
            Description = "Joint angles in degrees, comma-separated, one per joint (default: all zero)",
        };
        var command = new Command("fk", "Forward kinematics: tool pose, Jacobian and manipulability for a joint vector.");
        command.Arguments.Add(robotArgument);
        command.Options.Add(jointsOption);
        command.SetAction(parse => Run(
            parse.GetValue(robotArgument)!.FullName,
            parse.GetValue(jointsOption),
            parse.InvocationConfiguration.Output,
            parse.InvocationConfiguration.Error));
        return command;
    }

    /// <summary>Runs the command; returns the exit code (0 ok, 2 bad input).</summary>
    internal static int Run(string robotPath, string? jointsDeg, TextWriter output, TextWriter error)
    {
        if (RobotFiles.LoadOrReport(robotPath, error) is not { } robot)
        {
            return 2;
        }

        if (!TryParseJoints(jointsDeg, robot.JointCount, out var q, out var problem))
        {
            error.WriteLine($"--joints-deg: {problem}");
            return 2;
        }

        var chain = new KinematicChain(robot);
        var state = chain.CreateState();
        state.Update(q);
        var n = chain.JointCount;
        var jacobian = new double[6 * n];
        state.Jacobian(jacobian);

        if (!double.IsFinite(state.ToolPose.Position.X + state.ToolPose.Position.Y + state.ToolPose.Position.Z) || !jacobian.All(double.IsFinite))
        {
            error.WriteLine($"{robot.SourceFile}: the tool pose or Jacobian at these joint angles is not finite; check the file's lengths and angles");
            return 1;
        }

        var c = CultureInfo.InvariantCulture;
        output.WriteLine(string.Create(c, $"{robot.Name} ({robot.SourceFile})"));
        output.WriteLine("joints (deg):");
        for (var j = 0; j < n; j++)
        {
            var joint = robot.Joints[j];
            var limit = q[j] >= joint.MinRad && q[j] <= joint.MaxRad ? string.Empty : "   OUTSIDE RANGE";
            output.WriteLine(string.Create(c, $"  {joint.Symbol,-5} {joint.Name,-15} {q[j] / Deg,10:F3}   range [{joint.MinRad / Deg:F1}, {joint.MaxRad / Deg:F1}]{limit}"));
        }

        var pose = state.ToolPose;
        var (roll, pitch, yaw) = pose.Rotation.ToRollPitchYaw();
        output.WriteLine(string.Create(c, $"tool position (mm): {Format(pose.Position)}"));
        output.WriteLine("tool rotation (columns are the tool's x, y, z axes):");
        for (var row = 0; row < 3; row++)
        {
            output.WriteLine(string.Create(c, $"  {Clean(pose.Rotation.At(row, 0)),10:F6} {Clean(pose.Rotation.At(row, 1)),10:F6} {Clean(pose.Rotation.At(row, 2)),10:F6}"));
        }

        output.WriteLine(string.Create(c, $"tool roll/pitch/yaw (deg, R = Rz(yaw) Ry(pitch) Rx(roll)): {roll / Deg:F4}, {pitch / Deg:F4}, {yaw / Deg:F4}"));
        output.WriteLine("geometric Jacobian (rows vx, vy, vz in mm/rad; wx, wy, wz in rad/rad):");
        string[] rowNames = ["vx", "vy", "vz", "wx", "wy", "wz"];
        for (var row = 0; row < 6; row++)
        {
            output.Write(string.Create(c, $"  {rowNames[row]}"));
            for (var j = 0; j < n; j++)
            {
                output.Write(string.Create(c, $" {Clean(jacobian[(row * n) + j]),11:F4}"));
            }

            output.WriteLine();
        }

        var positionJoints = robot.PositionJoints.ToArray();
        output.WriteLine(string.Create(c, $"manipulability sqrt(det(J Jt)), position rows (mm^3): all joints {Manipulability.Of(state):F3}; position joints ({string.Join(", ", positionJoints.Select(j => robot.Joints[j].Symbol))}) {Manipulability.Of(state, positionJoints):F3}"));

        var map = new JointMotorMap(robot);
        var motors = new double[n];
        map.JointsToMotors(q, motors);
        output.WriteLine("motor shaft angles (turns) after the couplings and reductions:");
        for (var k = 0; k < n; k++)
        {
            output.WriteLine(string.Create(c, $"  {map.Actuators[k].Name,-15} {motors[k] / (2 * Math.PI),12:F3}"));
        }

        WriteClosedFormCheck(robot, q, pose.Position, output);
        return 0;
    }

    private static void WriteClosedFormCheck(RobotDefinition robot, double[] q, Vector3d position, TextWriter output)
    {
        CrbPositionIk ik;
        try
        {
            ik = new CrbPositionIk(robot);
        }
        catch (ArgumentException)
        {
            return; // not a CRB-type arm: no closed form
        }

        var solved = (double[])q.Clone();
        var status = ik.Solve(position, solved);
        var c = CultureInfo.InvariantCulture;
        output.WriteLine(status == CrbIkStatus.Solved
            ? string.Create(c, $"closed-form position IK of the tool position (deg): {solved[0] / Deg:F6}, {solved[1] / Deg:F6}, {solved[2] / Deg:F6}")
            : $"closed-form position IK of the tool position: {status} (elbow up, no inverted shoulder, within the joint ranges)");
    }

    internal static bool TryParseJoints(string? text, int count, out double[] radians, out string problem)
    {
        radians = new double[count];
        problem = string.Empty;
        if (string.IsNullOrWhiteSpace(text))
        {
            return true;
        }

        var parts = text.Split(',', StringSplitOptions.TrimEntries);
        if (parts.Length != count)
        {
            problem = $"{parts.Length} values given; the robot has {count} joints";
            return false;
        }

        for (var j = 0; j < count; j++)
        {
            if (!double.TryParse(parts[j], NumberStyles.Float, CultureInfo.InvariantCulture, out var degrees) || !double.IsFinite(degrees))
            {
                problem = $"value {j + 1} (\"{parts[j]}\") is not a finite number";
                return false;
            }

            radians[j] = degrees * Deg;
        }

        return true;
    }

    private static string Format(Vector3d v) =>
        string.Create(CultureInfo.InvariantCulture, $"{Clean(v.X):F4}, {Clean(v.Y):F4}, {Clean(v.Z):F4}");

    // Rounding leaves values like -3e-15 where the exact value is 0; print them as 0, not "-0.0000".
    private static double Clean(double value) => Math.Abs(value) < 1e-9 ? 0.0 : value;
}
