using RobotControl.Definitions.Model;
using RobotControl.Host.Safety;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Control;
using RobotControl.Robot.States;

namespace RobotControl.Host.Harness;

/// <summary>
/// When a run must stop: a stop request (Ctrl+C, SIGTERM), or a robot fault that leaves the arm unable to follow
/// its commands (a module stopped its motors, latched a hardware error or stopped answering, or a safety trip
/// switched the motors off) unless the run was told to continue. A trip whose safe state is hold does not end the
/// run: the arms hold at E-STOP and the report names the trip. A module counts as stopped answering once it has been
/// missing for longer than its bus watchdog's second stage (<c>modules.watchdog_off_ms</c>: by then it has stopped its
/// motors itself); a few lost replies on a busy link do not stop the run.
/// Checked once per bus cycle (virtual) or every few milliseconds (real time); allocates only when it stops.
/// </summary>
internal sealed class FaultStop(BusRobot robot, bool continueOnFault, CancellationToken stop, SafetySupervisor? supervisor = null)
{
    private readonly TimeProvider _clock = robot.Client.Time;
    private readonly long _grace = robot.Client.Time.TimestampFrequency * Math.Max(1, robot.Definition.Modules.WatchdogOffMs) / 1000;
    private long _missingSince = -1;

    /// <summary>The fault that stopped the run (null: none).</summary>
    public string? Fault { get; private set; }

    /// <summary>True when a stop was requested.</summary>
    public bool Interrupted => stop.IsCancellationRequested;

    /// <summary>True when the run must end now.</summary>
    public bool ShouldStop()
    {
        if (stop.IsCancellationRequested || Fault is not null)
        {
            return true;
        }

        if (continueOnFault)
        {
            return false;
        }

        if (supervisor is { MotorsTrippedOff: true })
        {
            var trip = supervisor.Trips.LastOrDefault(t => t.Action == SafeState.TorqueOff);
            var what = trip is null ? "a safety trip" : $"safety trip {trip.Check.Name()} {trip.Joint}".TrimEnd();
            var cause = robot.StateHistory.LastOrDefault(t => t.To == RobotState.Fault)?.Reason;
            Fault = cause is null ? $"{what} switched the motors off" : $"{what} switched the motors off ({cause})";
            return true;
        }

        if (robot.State == RobotState.Fault)
        {
            var history = robot.StateHistory;
            Fault = history.Count > 0 ? history[^1].Reason : "the robot is in fault";
            return true;
        }

        if ((robot.Faults & RobotFaults.ModuleMissing) == 0)
        {
            _missingSince = -1;
            return false;
        }

        var now = _clock.GetTimestamp();
        if (_missingSince < 0)
        {
            _missingSince = now;
        }

        if (now - _missingSince > _grace)
        {
            var missing = robot.Controllers.Where(c => !c.Present).Select(c => $"{c.Id} \"{c.Name}\"");
            Fault = $"module(s) {string.Join(", ", missing)} stopped answering for more than {robot.Definition.Modules.WatchdogOffMs} ms";
            return true;
        }

        return false;
    }
}
