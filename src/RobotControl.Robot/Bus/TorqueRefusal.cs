using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;

namespace RobotControl.Robot.Bus;

/// <summary>
/// Why a module refused to switch torque, from the two replies and its status read afterwards: a latched watchdog is
/// named only when the module says it is latched; otherwise the latched errors it reports, a module that did not
/// answer, or the status packet's error code.
/// </summary>
internal static class TorqueRefusal
{
    /// <summary>The one-line message for module <paramref name="id"/> "<paramref name="name"/>".</summary>
    /// <param name="id">Module ID.</param>
    /// <param name="name">Module name.</param>
    /// <param name="on">True when torque was being switched on.</param>
    /// <param name="torque">Reply to the torque write.</param>
    /// <param name="watchdog">Reply to the watchdog write that failed (its stage 2 or stage 1), or to the last one.</param>
    /// <param name="status">hardware_error_status and reset_cause, or null when they could not be read.</param>
    public static string Describe(byte id, string name, bool on, Reply torque, Reply watchdog, (HardwareErrors Errors, byte ResetCause)? status)
    {
        var replies = $"torque {torque.Outcome} {StatusErrors.Describe(torque.Error)}, watchdog {watchdog.Outcome} {StatusErrors.Describe(watchdog.Error)}";
        var cause = status switch
        {
            { Errors: var e } when e.HasFlag(HardwareErrors.BusWatchdog) => $"its bus watchdog error is latched ({e}, reset cause {status.Value.ResetCause}): clear the module's errors first",
            { Errors: var e } when e.HasFlag(HardwareErrors.BusHold) => $"it holds its motors after a bus silence ({e}, reset cause {status.Value.ResetCause}): acknowledge the hold first (BusRobot.RequestHoldAcknowledgement)",
            { Errors: var e } when !e.IsNone => $"it reports latched errors {e} (reset cause {status.Value.ResetCause}): clear them first",
            null when torque.Outcome != ReplyOutcome.Ok && watchdog.Outcome != ReplyOutcome.Ok => "the module does not answer",
            null => "its status could not be read",
            _ => $"the module refused the write ({StatusErrors.Describe(torque.Succeeded ? watchdog.Error : torque.Error)}) without a latched error",
        };
        return $"module {id} \"{name}\": torque {(on ? "on" : "off")} refused ({replies}); {cause}";
    }
}
