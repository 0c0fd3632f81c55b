using System.Buffers.Binary;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Robot.Bus;
using RobotControl.Robot.States;
using RobotControl.Simulation;

namespace RobotControl.Robot.Tests.Bus.Core;

/// <summary>
/// Homing's verification, motor by motor: what each result says when a request, a read-back or the module's error
/// bits let it down, the state homing leaves the robot in, and homing one motor alone.
/// </summary>
public sealed class HomingVerificationTests
{
    private const double Deg = Math.PI / 180;
    private static readonly ControlTable Table = ControlTable.Firmware;

    [Fact]
    public void A_complete_homing_says_so_and_each_result_has_no_detail()
    {
        using var rig = new TappedLb();
        rig.Robot.EnableTorque(false);
        var results = rig.Robot.Home();
        Assert.All(results, r => Assert.Equal((HomingOutcome.Homed, string.Empty), (r.Outcome, r.Detail)));
        Assert.All(results, r => Assert.InRange(r.PotRaw, 1, 4095));
        Assert.Equal((RobotState.Homed, "homing", "12 motors homed and verified"), (rig.Robot.State, rig.Robot.StateHistory[^1].Source, rig.Robot.StateHistory[^1].Reason));
    }

    [Fact]
    public void A_module_whose_calibration_cannot_be_read_is_reported_for_each_motor_and_the_others_are_homed()
    {
        using var rig = new TappedLb();
        rig.Robot.EnableTorque(false);
        rig.Tap.Mute(3);

        var results = rig.Robot.Home();

        Assert.All(results.Where(r => r.Motor.Controller.Id == 3), r =>
        {
            Assert.Equal((HomingOutcome.NoReply, "reading the module's pot calibration failed", -1), (r.Outcome, r.Detail, r.PotRaw));
            Assert.True(double.IsNaN(r.PositionRad) && double.IsNaN(r.PotPositionRad));
        });
        Assert.Equal(2, results.Count(r => r.Motor.Controller.Id == 3));
        Assert.All(results.Where(r => r.Motor.Controller.Id != 3), r => Assert.True(r.Succeeded, r.ToString()));
        Assert.Equal((RobotState.Discovered, "homing incomplete: 2 of 12 motors not homed"), (rig.Robot.State, rig.Robot.StateHistory[^1].Reason));
    }

    [Fact]
    public void A_home_request_that_gets_no_reply_is_reported()
    {
        using var rig = new TappedLb();
        rig.Robot.EnableTorque(false);
        rig.Tap.Lose = f => f.IsWrite(2, Table["home_request"].At(0));

        var results = rig.Robot.Home();

        var elbow = Assert.Single(results, r => r.Motor.Controller.Id == 2);
        Assert.Equal((HomingOutcome.NoReply, "the home request got no valid reply (Timeout)"), (elbow.Outcome, elbow.Detail));
        Assert.Equal(11, results.Count(r => r.Succeeded));
        Assert.Equal(RobotState.Discovered, rig.Robot.State);
    }

    [Theory]
    [InlineData("pot_raw")]
    [InlineData("present_position")]
    [InlineData("motor_error")]
    public void A_read_back_that_fails_leaves_the_motor_not_homed(string field)
    {
        using var rig = new TappedLb();
        rig.Robot.EnableTorque(false);
        var address = Table[field].At(0);
        rig.Tap.Lose = f => f.IsRead(2, address);

        var results = rig.Robot.Home();

        var elbow = Assert.Single(results, r => r.Motor.Controller.Id == 2);
        Assert.Equal((HomingOutcome.NoReply, "reading the pot, position or errors back failed"), (elbow.Outcome, elbow.Detail));
        Assert.Equal(field == "pot_raw", elbow.PotRaw == -1);
        Assert.Equal(field == "pot_raw", double.IsNaN(elbow.PotPositionRad));
        Assert.Equal(field == "present_position", double.IsNaN(elbow.PositionRad));
        Assert.Equal(11, results.Count(r => r.Succeeded));
    }

    [Fact]
    public void A_motor_whose_error_bits_stay_set_after_the_request_is_not_verified()
    {
        using var rig = new TappedLb();
        rig.Robot.EnableTorque(false);
        var errors = Table["motor_error"].At(0);
        rig.Tap.Rewrite = (request, reply) => request is { } r && r.IsRead(11, errors) ? reply with { Parameters = [0, (byte)(HardwareErrors.PotMismatch | HardwareErrors.OverCurrent).Value, 0] } : null;

        var results = rig.Robot.Home();

        var pitch = Assert.Single(results, r => r.Motor.Config.FullName == "left.shoulder_pitch");
        Assert.Equal(HomingOutcome.VerifyFailed, pitch.Outcome);
        Assert.Equal($"error bits still set: {HardwareErrors.PotMismatch}", pitch.Detail);
        Assert.Equal(HardwareErrors.PotMismatch | HardwareErrors.OverCurrent, pitch.MotorErrors);
        var yaw = Assert.Single(results, r => r.Motor.Config.FullName == "left.shoulder_yaw");
        Assert.True(yaw.Succeeded);
        Assert.Equal(HardwareErrors.None, yaw.MotorErrors);
    }

    [Fact]
    public void A_motor_whose_position_disagrees_with_its_pot_after_the_request_is_not_verified()
    {
        using var rig = new TappedLb();
        rig.Robot.EnableTorque(false);
        var pot = Table["pot_raw"].At(0);
        int? raw = null;
        rig.Tap.Rewrite = (request, reply) =>
        {
            if (request is not { } r || !r.IsRead(2, pot))
            {
                return null;
            }

            raw = BinaryPrimitives.ReadUInt16LittleEndian(reply.Parameters) + 600; // the pot moved by some 30 degrees since
            var changed = new byte[2];
            BinaryPrimitives.WriteUInt16LittleEndian(changed, (ushort)raw.Value);
            return reply with { Parameters = changed };
        };

        var results = rig.Robot.Home();

        var elbow = Assert.Single(results, r => r.Motor.Controller.Id == 2);
        Assert.Equal(HomingOutcome.VerifyFailed, elbow.Outcome);
        Assert.Equal(raw, elbow.PotRaw);
        Assert.Matches(@"^position -?\d+ differs from the pot's -?\d+ by \d+ counts \(tolerance \d+\)$", elbow.Detail);
        Assert.InRange(elbow.ErrorRad, -40 * Deg, -20 * Deg);
    }

    [Fact]
    public void A_module_without_calibrated_motors_gets_no_home_request()
    {
        using var rig = new TappedLb(start: false, sim: new VirtualRobotOptions { Commissioned = false });
        rig.Robot.Discover();
        Assert.All(rig.Robot.Home(), r => Assert.Equal(HomingOutcome.NotCalibrated, r.Outcome));
        Assert.DoesNotContain(rig.Tap.Sent, f => f.Address == Table["home_request"].At(0));
        Assert.Equal((RobotState.Discovered, "homing incomplete: 12 of 12 motors not homed"), (rig.Robot.State, rig.Robot.StateHistory[^1].Reason));
    }

    [Fact]
    public void Homing_one_motor_homes_its_channel_alone_from_its_pot()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        robot.EnableTorque(false);
        var pitchAxis = rig.Sim.Axis(0, "shoulder_2");
        var pitch = robot.Motor(pitchAxis.Config.FullName);
        var yaw = robot.Motor("right.shoulder_yaw");
        var yawBefore = yaw.PositionRad;
        rig.Sim.TurnWhileOff(pitchAxis, pitchAxis.OutputAngleRad + (20 * Deg)); // the module resumes the stale position
        rig.Sim.Advance(TimeSpan.FromMilliseconds(2));
        Span<double> before = stackalloc double[5];
        robot.ReadJointPositions(0, before);

        var result = robot.HomeMotor(pitch);

        Assert.Equal((HomingOutcome.Homed, string.Empty), (result.Outcome, result.Detail));
        Assert.Same(pitch, result.Motor);
        Assert.InRange(result.PositionRad - pitchAxis.OutputAngleRad, -0.5 * Deg, 0.5 * Deg);
        Assert.Equal(result.PositionRad, pitch.PositionRad);
        Assert.InRange(result.PotRaw, 1, 4095);
        Assert.Equal(HardwareErrors.None, result.MotorErrors);
        Assert.Equal(yawBefore, yaw.PositionRad); // not homed, not read
        Assert.Contains(rig.Tap.Sent, f => f.IsWrite(1, Table["home_request"].At(0)) && f.Parameters[2] == 0b010);

        // The arm's joints follow the homed position at once.
        Span<double> after = stackalloc double[5];
        robot.ReadJointPositions(0, after);
        Assert.NotEqual(before.ToArray(), after.ToArray());
    }

    [Fact]
    public void Homing_one_motor_is_refused_with_the_motors_on_and_reports_a_refusing_or_silent_module()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        var elbow = robot.Motor("right.elbow");
        var refused = Assert.Throws<InvalidOperationException>(() => robot.HomeMotor(elbow));
        Assert.Equal("homing right.elbow needs the robot Discovered or Homed, it is Enabled: turn the motors off first: a driven motor must not change coordinates", refused.Message);
        Assert.Throws<ArgumentNullException>(() => robot.HomeMotor(null!));

        robot.EnableTorque(false);
        Assert.True(robot.Client.Write(2, Table["torque_enable"].At(0), [1]).Succeeded); // driven behind the robot's back
        var result = robot.HomeMotor(elbow);
        Assert.Equal(HomingOutcome.Refused, result.Outcome);
        Assert.StartsWith("the module refused the home request (status error ", result.Detail, StringComparison.Ordinal);
        Assert.EndsWith("): torque on, or no pot calibration?", result.Detail, StringComparison.Ordinal);

        Assert.True(robot.Client.Write(2, Table["torque_enable"].At(0), [0]).Succeeded);
        rig.Tap.Lose = f => f.IsWrite(2, Table["home_request"].At(0));
        result = robot.HomeMotor(elbow);
        Assert.Equal((HomingOutcome.NoReply, "the home request got no valid reply (Timeout)"), (result.Outcome, result.Detail));
    }
}
