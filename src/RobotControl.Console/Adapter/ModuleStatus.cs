using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Robot.Bus;

namespace RobotControl.WebConsole.Adapter;

/// <summary>Volatile state of one module read by the status poll (session thread).</summary>
internal sealed record ModuleStatus(HardwareErrors Errors, int ResetCause, int WatchdogMs, int[] Pwm, bool[] Torque, HardwareErrors[] MotorErrors)
{
    /// <summary>Nothing read yet.</summary>
    public static ModuleStatus Unknown(int channels) => new(HardwareErrors.None, 0, 0, new int[channels], new bool[channels], new HardwareErrors[channels]);

    /// <summary>Reads the status of <paramref name="c"/> (module-wide errors, reset cause, watchdog, per-motor PWM, torque, errors).</summary>
    /// <exception cref="IOException">The module does not answer.</exception>
    public static ModuleStatus Read(BusRobot bus, RobotController c)
    {
        var channels = c.Motors.Count == 0 ? 1 : c.Motors.Max(m => m.Config.Channel) + 1;
        var pwm = new int[channels];
        var torque = new bool[channels];
        var errors = new HardwareErrors[channels];
        foreach (var m in c.Motors)
        {
            var ch = m.Config.Channel;
            pwm[ch] = (int)bus.ReadParameter(c.Id, "present_pwm", ch);
            torque[ch] = bus.ReadParameter(c.Id, "torque_enable", ch) != 0;
            errors[ch] = (HardwareErrors)bus.ReadParameter(c.Id, "motor_error", ch);
        }

        return new ModuleStatus(
            (HardwareErrors)bus.ReadParameter(c.Id, "hardware_error_status"),
            (int)bus.ReadParameter(c.Id, "reset_cause"),
            (int)bus.ReadParameter(c.Id, "bus_watchdog"),
            pwm,
            torque,
            errors);
    }

    /// <summary>Names of the set bits of <paramref name="bits"/>, as the control table names them.</summary>
    public static IReadOnlyList<string> Names(HardwareErrors bits) =>
        bits.IsNone ? [] : bits.ToString().Split(", ");

    /// <summary>A reset cause in words, as the control table names it.</summary>
    public static string Cause(int cause) =>
        cause == 0 ? "none since acknowledged"
        : ControlTable.Firmware.Codes("reset_cause").TryGetValue(cause, out var name) ? name : $"cause {cause}";
}
