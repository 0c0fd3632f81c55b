using RobotControl.Kinematics.Coupling;
using RobotControl.Kinematics.Forward;

namespace RobotControl.Kinematics.Tests.Coupling;

public sealed class JointMotorMapTests
{
    public static TheoryData<string> Robots => TestRobots.Names;

    [Theory]
    [MemberData(nameof(Robots))]
    public void Joint_to_motor_to_joint_round_trips_within_1e_12(string file)
    {
        var robot = TestRobots.ByFile(file);
        var map = new JointMotorMap(robot);
        var n = map.JointCount;
        var q = new double[n];
        var motors = new double[n];
        var actuators = new double[n];
        var back = new double[n];
        var chain = new KinematicChain(robot);
        var random = new Random(3);
        for (var sample = 0; sample < 1000; sample++)
        {
            TestRobots.FillRandomJoints(chain, random, q);

            map.JointsToMotors(q, motors);
            map.MotorsToJoints(motors, back);
            for (var j = 0; j < n; j++)
            {
                Assert.True(Math.Abs(back[j] - q[j]) <= 1e-12, $"joint {j}: {q[j]} -> {back[j]}");
            }

            map.JointsToActuators(q, actuators);
            map.ActuatorsToJoints(actuators, back);
            for (var j = 0; j < n; j++)
            {
                Assert.True(Math.Abs(back[j] - q[j]) <= 1e-12);
                Assert.Equal(actuators[j] * map.Ratio(j), motors[j], 1e-9);
            }
        }
    }

    [Fact]
    public void Crb_differential_shoulder_follows_robots_md()
    {
        var map = new JointMotorMap(TestRobots.Crb);
        double[] q = [0.3, -0.7, 1.1, 0.25];
        var a = new double[4];
        map.JointsToActuators(q, a);
        Assert.Equal(q[0] + q[1], a[map.IndexOfActuator("shoulder_1")], 15); // upper sun gear = phi1 + phi2
        Assert.Equal(q[0] - q[1], a[map.IndexOfActuator("shoulder_2")], 15); // lower sun gear = phi1 - phi2
        Assert.Equal(q[2], a[map.IndexOfActuator("elbow")], 15);
        Assert.Equal(q[3], a[map.IndexOfActuator("tool_roll")], 15);
    }

    [Fact]
    public void Lb_three_shaft_shoulder_follows_robots_md()
    {
        var map = new JointMotorMap(TestRobots.Lb);
        double[] q = [0.3, -0.7, 0.45, 1.1, 0.25];
        var a = new double[5];
        map.JointsToActuators(q, a);
        Assert.Equal(q[0] + q[1], a[map.IndexOfActuator("shoulder_1")], 15); // upper = phi1 + phi2
        Assert.Equal(q[0] - q[1], a[map.IndexOfActuator("shoulder_2")], 15); // lower = phi1 - phi2
        Assert.Equal(q[2] - q[0] - q[1], a[map.IndexOfActuator("shoulder_3")], 15); // middle = phi3 - phi1 - phi2
        Assert.Equal(q[3], a[map.IndexOfActuator("elbow")], 15);
        Assert.Equal(q[4], a[map.IndexOfActuator("tool_roll")], 15);
    }

    [Fact]
    public void Motor_angles_are_actuator_angles_times_the_total_reduction()
    {
        var robot = TestRobots.Crb;
        var map = new JointMotorMap(robot);
        double[] q = [0.1, 0.2, 0.3, 0.4];
        var m = new double[4];
        map.JointsToMotors(q, m);
        // shoulder_1: 30:12 spur stage after a 256:1 gearhead.
        Assert.Equal((0.1 + 0.2) * (30.0 / 12.0) * 256, m[0], 1e-12);
        // elbow: 16:10 after 1024:1.
        Assert.Equal(0.3 * (16.0 / 10.0) * 1024, m[2], 1e-12);
    }

    [Theory]
    [MemberData(nameof(Robots))]
    public void Torques_map_by_the_transpose_so_power_is_conserved(string file)
    {
        var map = new JointMotorMap(TestRobots.ByFile(file));
        var n = map.JointCount;
        var random = new Random(5);
        var jointRates = Enumerable.Range(0, n).Select(_ => random.NextDouble() - 0.5).ToArray();
        var actuatorTorques = Enumerable.Range(0, n).Select(_ => random.NextDouble() - 0.5).ToArray();
        var actuatorRates = new double[n];
        var jointTorques = new double[n];
        var torquesBack = new double[n];
        map.JointsToActuators(jointRates, actuatorRates);
        map.ActuatorTorquesToJointTorques(actuatorTorques, jointTorques);
        map.JointTorquesToActuatorTorques(jointTorques, torquesBack);
        var actuatorPower = actuatorTorques.Zip(actuatorRates, (t, w) => t * w).Sum();
        var jointPower = jointTorques.Zip(jointRates, (t, w) => t * w).Sum();
        Assert.Equal(actuatorPower, jointPower, 1e-12);
        for (var k = 0; k < n; k++)
        {
            Assert.Equal(actuatorTorques[k], torquesBack[k], 1e-12);
        }
    }

    [Theory]
    [MemberData(nameof(Robots))]
    public void Tool_jaw_maps_through_its_own_drivetrain(string file)
    {
        var robot = TestRobots.ByFile(file);
        var map = new JointMotorMap(robot);
        Assert.NotNull(map.ToolActuator);
        Assert.Equal("tool_open_close", map.ToolActuator!.Name);
        Assert.Equal(-1, map.IndexOfActuator("tool_open_close"));
        var jaw = 0.5 * (map.JawMinRad + map.JawMaxRad);
        var motor = map.JawToMotor(jaw);
        Assert.Equal(jaw * map.ToolActuator.Drivetrain.TotalRatio, motor, 1e-12);
        Assert.Equal(jaw, map.MotorToJaw(motor), 1e-15);
    }

    [Fact]
    public void Mapping_is_allocation_free()
    {
        var map = new JointMotorMap(TestRobots.Lb);
        var q = new double[5] { 0.1, 0.2, 0.3, 0.4, 0.5 };
        var m = new double[5];
        map.JointsToMotors(q, m);
        map.MotorsToJoints(m, q);
        var before = GC.GetAllocatedBytesForCurrentThread();
        for (var i = 0; i < 100; i++)
        {
            map.JointsToMotors(q, m);
            map.MotorsToJoints(m, q);
            _ = map.MotorToJaw(map.JawToMotor(0.2));
        }

        Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
    }

    [Fact]
    public void Rejects_overlapping_and_short_vectors()
    {
        var map = new JointMotorMap(TestRobots.Crb);
        var buffer = new double[4];
        Assert.Throws<ArgumentException>(() => map.JointsToMotors(buffer, buffer));
        Assert.Throws<ArgumentException>(() => map.JointsToMotors(new double[3], new double[4]));
    }
}
