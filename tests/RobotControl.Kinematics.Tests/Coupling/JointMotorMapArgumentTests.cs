using System.Text.Json.Nodes;
using RobotControl.Definitions.Loading;
using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Coupling;

namespace RobotControl.Kinematics.Tests.Coupling;

/// <summary>The map's coefficients, its refusals and each mapping's checks, against the CRB-1.0 coupling of docs/robots.md.</summary>
public sealed class JointMotorMapArgumentTests
{
    private delegate void Mapping(JointMotorMap map, double[] input, double[] output);

    private static readonly Mapping[] Mappings =
    [
        (m, i, o) => m.JointsToActuators(i, o),
        (m, i, o) => m.ActuatorsToJoints(i, o),
        (m, i, o) => m.JointsToMotors(i, o),
        (m, i, o) => m.MotorsToJoints(i, o),
        (m, i, o) => m.ActuatorTorquesToJointTorques(i, o),
        (m, i, o) => m.JointTorquesToActuatorTorques(i, o),
    ];

    private static RobotDefinition ChangedCrb(Action<JsonNode> change)
    {
        var json = JsonNode.Parse(File.ReadAllText(TestRobots.PathOf("crb-1.0.json")))!;
        change(json);
        return RobotLoader.LoadFromText(json.ToJsonString(), TestRobots.PathOf("crb-changed.json"));
    }

    [Fact]
    public void Coefficients_are_the_differential_shoulder_and_its_inverse()
    {
        // C rows (actuators) x columns (joints): shoulder_1 = phi1 + phi2, shoulder_2 = phi1 - phi2, elbow, roll.
        // Its inverse: phi1 = (a1 + a2) / 2, phi2 = (a1 - a2) / 2.
        var map = new JointMotorMap(TestRobots.Crb);
        double[,] c = { { 1, 1, 0, 0 }, { 1, -1, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };
        double[,] inverse = { { 0.5, 0.5, 0, 0 }, { 0.5, -0.5, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };
        for (var r = 0; r < 4; r++)
        {
            for (var k = 0; k < 4; k++)
            {
                Assert.Equal(c[r, k], map.Coefficient(r, k), 15);
                Assert.Equal(inverse[r, k], map.InverseCoefficient(r, k), 15);
            }
        }
    }

    [Fact]
    public void Actuator_angles_map_back_to_hand_derived_joint_angles()
    {
        var map = new JointMotorMap(TestRobots.Crb);
        var joints = new double[4];
        map.ActuatorsToJoints([0.4, -0.2, 0.7, -0.3], joints);
        Assert.Equal([0.1, 0.3, 0.7, -0.3], joints, (a, b) => Math.Abs(a - b) < 1e-15);
    }

    [Fact]
    public void Every_mapping_refuses_short_and_overlapping_vectors()
    {
        var map = new JointMotorMap(TestRobots.Crb);
        foreach (var mapping in Mappings)
        {
            var buffer = new double[4];
            Assert.Throws<ArgumentException>(() => mapping(map, buffer, buffer));
            Assert.Throws<ArgumentException>(() => mapping(map, new double[3], new double[4]));
            Assert.Throws<ArgumentException>(() => mapping(map, new double[4], new double[3]));
            mapping(map, new double[4], new double[4]);
        }
    }

    [Fact]
    public void A_coupling_the_loader_accepts_but_too_ill_conditioned_to_invert_is_refused()
    {
        // Rows (1, 1) and (1, 1 + 1e-8): invertible to the loader (pivot 1e-8 > 1e-9), condition number about 4e8.
        var robot = ChangedCrb(json => json["actuators"]![1]!["coupling"]!["shoulder_pitch"] = 1 + 1e-8);
        var message = Assert.Throws<ArgumentException>(() => new JointMotorMap(robot)).Message;
        Assert.Contains("the coupling matrix of the kinematic actuators is singular", message, StringComparison.Ordinal);
    }

    [Fact]
    public void A_robot_without_a_tool_drive_maps_its_joints_and_says_so_for_the_jaw()
    {
        var robot = ChangedCrb(json =>
        {
            json["actuators"]!.AsArray().RemoveAt(4);
            foreach (var module in json["modules"]!["layout"]!.AsArray())
            {
                var motors = module!["motors"]!.AsArray();
                foreach (var motor in motors.Where(m => (string?)m!["actuator"] == "tool_open_close").ToList())
                {
                    motors.Remove(motor);
                }
            }
        });
        var map = new JointMotorMap(robot);
        Assert.Null(map.ToolActuator);
        Assert.Throws<InvalidOperationException>(() => map.JawToMotor(0.1));
        Assert.Throws<ArgumentNullException>(() => new JointMotorMap(null!));
    }
}
