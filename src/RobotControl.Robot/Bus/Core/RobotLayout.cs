using RobotControl.Bus.Protocol;
using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Coupling;
using RobotControl.Modules;

namespace RobotControl.Robot.Bus;

/// <summary>
/// What the robot file and the control table fix for a robot on its bus, built once: its controllers and motors
/// (named after the joints), which motor drives which actuator of which arm, the joint &lt;-&gt; motor mapping and the
/// addresses the cycle uses. Nothing in it changes afterwards.
/// </summary>
[WrittenBy(RobotThread.None)]
internal sealed class RobotLayout
{
    /// <summary>Bytes the status poll reads per module: <c>hardware_error_status</c>, <c>reset_cause</c>, <c>bus_watchdog</c> (u16).</summary>
    public const int StatusPollLength = 4;

    public RobotLayout(RobotDefinition robot)
    {
        Definition = robot;
        Table = ControlTable.Firmware;
        Map = new JointMotorMap(robot);
        KinematicActuator = [.. Map.Actuators.Select(a => IndexOf(robot, a))];
        ToolActuator = Map.ToolActuator is { } tool ? IndexOf(robot, tool) : -1;
        WatchdogMs = robot.Modules.WatchdogMs;
        WatchdogOffMs = robot.Modules.WatchdogOffMs;

        var controllers = new List<RobotController>();
        var motors = new List<RobotMotor>();
        MotorOf = new RobotMotor?[robot.Arms.Count][];
        for (var arm = 0; arm < robot.Arms.Count; arm++)
        {
            MotorOf[arm] = new RobotMotor?[robot.Actuators.Count];
        }

        foreach (var module in robot.Modules.Modules)
        {
            var controller = new RobotController(module, controllers.Count);
            var own = new List<RobotMotor>();
            foreach (var m in module.Motors.OrderBy(m => m.Channel))
            {
                var motor = new RobotMotor(new MotorConfig(robot, module, m), controller, motors.Count);
                motors.Add(motor);
                own.Add(motor);
                MotorOf[module.Arm][m.ActuatorIndex] = motor;
            }

            controller.MotorArray = [.. own];
            controllers.Add(controller);
        }

        Controllers = [.. controllers];
        Motors = [.. motors];

        var goal = Table["goal_position"];
        var position = Table["present_position"];
        var maxChannels = Controllers.Max(c => c.ChannelSpan);
        GoalAddress = goal.At(0);
        GoalStride = goal.Stride;
        GoalLength = ((maxChannels - 1) * goal.Stride) + goal.Size;
        FeedbackAddress = position.At(0);
        FeedbackStride = position.Stride;
        CurrentOffset = Table["present_current"].At(0) - FeedbackAddress;
        PwmOffset = Table["present_pwm"].At(0) - FeedbackAddress;
        MotorErrorAddress = Table["motor_error"].At(0);
        StatusAddress = Table["hardware_error_status"].At(0);
        var pot = Table["pot_raw"];
        PotAddress = pot.At(0);
        PotStride = pot.Stride;
        PotLength = ((maxChannels - 1) * pot.Stride) + pot.Size;
        ResetCauseAddress = Table["reset_cause"].At(0);
        WatchdogAddress = Table["bus_watchdog"].At(0);
        WatchdogOffAddress = Table["bus_watchdog_off"].At(0);
        TorqueAddress = Table["torque_enable"].At(0);
        ResetCauses = Table.Codes("reset_cause");
        if (ResetCauseAddress != StatusAddress + 1 || WatchdogAddress != StatusAddress + 2 || Table["bus_watchdog"].Size != StatusPollLength - 2)
        {
            throw new InvalidOperationException("the control table no longer keeps reset_cause and bus_watchdog (2 bytes) right after hardware_error_status; update the status poll");
        }
    }

    public RobotDefinition Definition { get; }

    public ControlTable Table { get; }

    public JointMotorMap Map { get; }

    public RobotController[] Controllers { get; }

    public RobotMotor[] Motors { get; }

    /// <summary>[arm][actuator index in the robot file]: the motor driving it, or null.</summary>
    public RobotMotor?[][] MotorOf { get; }

    /// <summary>Kinematic index -> robot-file actuator index.</summary>
    public int[] KinematicActuator { get; }

    /// <summary>The tool (jaw) actuator's robot-file index, or -1.</summary>
    public int ToolActuator { get; }

    public int ArmCount => Definition.Arms.Count;

    public int JointCount => Definition.JointCount;

    /// <summary>The bus watchdog's stage 1 (the modules hold), ms: the robot file's <c>modules.watchdog_ms</c>.</summary>
    public int WatchdogMs { get; }

    /// <summary>The bus watchdog's stage 2 (the modules switch their motors off), ms: <c>modules.watchdog_off_ms</c>.</summary>
    public int WatchdogOffMs { get; }

    public ushort GoalAddress { get; }

    public int GoalStride { get; }

    public int GoalLength { get; }

    public ushort FeedbackAddress { get; }

    public int FeedbackStride { get; }

    /// <summary>Where a motor's current and PWM sit in its feedback block, from its position.</summary>
    public int CurrentOffset { get; }

    public int PwmOffset { get; }

    public ushort MotorErrorAddress { get; }

    public ushort StatusAddress { get; }

    public ushort PotAddress { get; }

    public int PotStride { get; }

    public int PotLength { get; }

    public ushort ResetCauseAddress { get; }

    public ushort WatchdogAddress { get; }

    public ushort WatchdogOffAddress { get; }

    public ushort TorqueAddress { get; }

    public IReadOnlyDictionary<int, string> ResetCauses { get; }

    /// <summary>The tool motor of <paramref name="arm"/>, or null.</summary>
    public RobotMotor? ToolMotor(int arm) => ToolActuator >= 0 ? MotorOf[arm][ToolActuator] : null;

    private static int IndexOf(RobotDefinition robot, ActuatorDefinition actuator)
    {
        for (var i = 0; i < robot.Actuators.Count; i++)
        {
            if (ReferenceEquals(robot.Actuators[i], actuator))
            {
                return i;
            }
        }

        return -1;
    }
}
