using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Robot.States;

namespace RobotControl.Robot.Bus;

/// <summary>
/// Homing from the joint pots, verified motor by motor, on the bus thread (between cycles). Each module gets one
/// <c>home_request</c> for its calibrated motors: the firmware sets their position, goal and setpoint to the pot
/// position (through its calibration table), clears their pot-mismatch and position-lost bits and saves the position
/// record. Then each motor's position is read back and compared with its pot through the same calibration (within the
/// module's <c>pot_mismatch_tolerance</c>), and its <c>motor_error</c> bits are checked. Motors without a pot
/// calibration keep their position (<see cref="HomingOutcome.NotCalibrated"/>). A module that refuses or does not
/// answer is reported for each of its motors; the others are still homed. Every transaction insists
/// (<see cref="BusRobot.InsistingRetries"/>): homing is set-up that must get through a stalled reply (a module process
/// starved of the CPU missed the default retries), and a second home request is harmless (the same pot, the same
/// position).
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class Homing(RobotLayout layout, BusClient client, ModuleRoster roster, RobotLifecycle life, RobotSetup setup, FeedbackExchange feedback)
{
    /// <summary>The source of the moves homing makes.</summary>
    private const string Source = "homing";

    public IReadOnlyList<HomingResult> HomeAll()
    {
        life.Machine.Require("homing", "it needs the robot discovered and the motors off: a driven motor must not change coordinates under the control loop; call EnableTorque(false) first", RobotState.Discovered, RobotState.Homed);
        var active = roster.Active.Controllers;
        life.Machine.MoveTo(RobotState.Homing, Source, $"homing {active.Length} modules from their pots");
        var results = new List<HomingResult>();
        try
        {
            foreach (var c in active)
            {
                HomeModule(c, results);
            }

            feedback.PublishFromMotors();
        }
        finally
        {
            var failed = results.Count(r => !r.Succeeded);
            var done = failed == 0 && results.Count == active.Sum(c => c.Motors.Count);
            life.Machine.MoveTo(done ? RobotState.Homed : RobotState.Discovered, Source, done ? $"{results.Count} motors homed and verified" : $"homing incomplete: {failed} of {results.Count} motors not homed");
        }

        return results;
    }

    /// <summary>Homes one motor: its module's home request for that channel alone, then the position read back (motors off).</summary>
    public HomingResult HomeOne(RobotMotor m)
    {
        life.Machine.Require($"homing {m.Config.FullName}", "turn the motors off first: a driven motor must not change coordinates", RobotState.Discovered, RobotState.Homed);
        var c = m.Controller;
        var ch = m.Config.Channel;
        var reply = client.Write(c.Id, layout.Table["home_request"].At(0), [(byte)(1 << ch)]);
        var position = setup.ReadParameter(c.Id, "present_position", ch);
        var errors = (HardwareErrors)setup.ReadParameter(c.Id, "motor_error", ch);
        var pot = (int)setup.ReadParameter(c.Id, "pot_raw", ch);
        var rad = m.Config.ToRadians(position);
        m.Publish(rad, m.CurrentA);
        feedback.PublishFromMotors();
        var outcome = reply.Outcome != ReplyOutcome.Ok ? HomingOutcome.NoReply : !reply.Succeeded ? HomingOutcome.Refused : HomingOutcome.Homed;
        var detail = outcome switch
        {
            HomingOutcome.NoReply => $"the home request got no valid reply ({reply.Outcome})",
            HomingOutcome.Refused => $"the module refused the home request (status error {StatusErrors.Describe(reply.Error)}): torque on, or no pot calibration?",
            _ => string.Empty,
        };
        return new HomingResult(m, outcome, pot, double.NaN, rad, errors, detail);
    }

    private void HomeModule(RobotController c, List<HomingResult> results)
    {
        var (start, end) = layout.Table.PersistentArea;
        var block = new byte[end - start];
        if (!client.ReadMapped(c.Id, layout.Table, start, block, BusRobot.InsistingRetries).Succeeded)
        {
            foreach (var m in c.Motors)
            {
                results.Add(new HomingResult(m, HomingOutcome.NoReply, -1, double.NaN, double.NaN, HardwareErrors.None, "reading the module's pot calibration failed"));
            }

            return;
        }

        var mask = 0;
        foreach (var m in c.Motors)
        {
            var table = PotCalibrationTable.Decode(layout.Table, block, start, m.Config.Channel);
            m.UsePotCalibration(table); // a unit's calibrated table, not the robot file's design curve
            if (table.IsCalibrated)
            {
                mask |= 1 << m.Config.Channel;
            }
        }

        var request = mask == 0 ? new Reply(ReplyOutcome.Ok, 0) : client.Write(c.Id, layout.Table["home_request"].At(0), [(byte)mask], BusRobot.InsistingRetries);
        var tolerance = PersistentValue(block, start, "pot_mismatch_tolerance", 0);
        var errors = new byte[c.ChannelSpan];
        var errorsRead = client.Read(c.Id, layout.Table["motor_error"].At(0), errors, BusRobot.InsistingRetries).Succeeded;
        foreach (var m in c.Motors)
        {
            var calibrated = ((mask >> m.Config.Channel) & 1) != 0;
            results.Add(VerifyHoming(m, calibrated, request, block, start, tolerance, errorsRead ? (HardwareErrors)errors[m.Config.Channel] : null));
        }
    }

    private HomingResult VerifyHoming(RobotMotor m, bool calibrated, Reply request, byte[] block, int start, long tolerance, HardwareErrors? errors)
    {
        var ch = m.Config.Channel;
        var hasRaw = setup.TryReadParameter(m.Controller.Id, "pot_raw", ch, out var raw, BusRobot.InsistingRetries).Succeeded;
        var hasPosition = setup.TryReadParameter(m.Controller.Id, "present_position", ch, out var position, BusRobot.InsistingRetries).Succeeded;
        var positionRad = hasPosition ? m.Config.ToRadians(position) : double.NaN;
        if (hasPosition)
        {
            m.Publish(positionRad, m.CurrentA);
        }

        var potRaw = hasRaw ? (int)raw : -1;
        var potPosition = hasRaw && calibrated ? PotCalibrationTable.Decode(layout.Table, block, start, ch).PositionAt(potRaw) : 0;
        var potRad = hasRaw && calibrated ? m.Config.ToRadians(potPosition) : double.NaN;
        var motorErrors = errors ?? HardwareErrors.None;
        HomingResult Result(HomingOutcome outcome, string detail) => new(m, outcome, potRaw, potRad, positionRad, motorErrors, detail);

        if (!calibrated)
        {
            return Result(HomingOutcome.NotCalibrated, "no pot calibration (pot_cal_count < 2): position kept; write the robot file's parameters (robotctl params) and home again");
        }

        if (request.Outcome != ReplyOutcome.Ok)
        {
            return Result(HomingOutcome.NoReply, $"the home request got no valid reply ({request.Outcome})");
        }

        if (!request.Succeeded)
        {
            return Result(HomingOutcome.Refused, $"the module refused the home request (status error {StatusErrors.Describe(request.Error)}): is torque on in the module, or a pot calibration missing?");
        }

        if (!hasRaw || !hasPosition || errors is null)
        {
            return Result(HomingOutcome.NoReply, "reading the pot, position or errors back failed");
        }

        var left = motorErrors & (HardwareErrors.PotMismatch | HardwareErrors.PositionLost);
        if (left != HardwareErrors.None)
        {
            return Result(HomingOutcome.VerifyFailed, $"error bits still set: {left}");
        }

        var diff = Math.Abs(position - potPosition);
        return diff > tolerance
            ? Result(HomingOutcome.VerifyFailed, $"position {position} differs from the pot's {potPosition} by {diff} counts (tolerance {tolerance})")
            : Result(HomingOutcome.Homed, string.Empty);
    }

    private long PersistentValue(byte[] block, int start, string field, int motor) =>
        layout.Table[field].Decode(block.AsSpan(layout.Table[field].At(motor) - start));
}
