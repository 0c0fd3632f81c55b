using RobotControl.Modules;
using RobotControl.Robot.Bus;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// <c>discover --clear-faults</c>: says which modules have a latched error (e.g. a tripped bus watchdog after a
/// crashed host) and then clears them deliberately, in the modules and in the robot, motors left off.
/// </summary>
internal static class LatchedFaults
{
    /// <summary>Prints and clears the latched errors; returns how many modules had one.</summary>
    public static int Clear(BusRobot robot, TextWriter output)
    {
        ArgumentNullException.ThrowIfNull(robot);
        var latched = robot.Controllers.Where(c => c.Present && c.HardwareErrorStatus != 0).ToList();
        foreach (var c in latched)
        {
            output.WriteLine($"LATCHED  module {c.Id} \"{c.Name}\": {new HardwareErrors(c.HardwareErrorStatus)}: clearing");
        }

        if (latched.Count > 0)
        {
            robot.ClearFaults();
            robot.RunCycle(); // the clear runs at the start of a cycle, motors off
        }

        output.WriteLine(latched.Count == 0 ? "no latched errors" : $"cleared the latched errors of {latched.Count} module(s)");
        return latched.Count;
    }
}
