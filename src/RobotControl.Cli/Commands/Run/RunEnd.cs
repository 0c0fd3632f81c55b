using System.Globalization;
using RobotControl.Host.Harness;
using RobotControl.Host.Session;

namespace RobotControl.Cli.Commands.Run;

/// <summary>How a run ended, said prominently, and its exit code.</summary>
internal static class RunEnd
{
    /// <summary>Exit code of an interrupted run (128 + SIGINT, as shells report it).</summary>
    public const int Interrupted = 130;

    /// <summary>0: clean; 130: interrupted; 1: a robot fault stopped it, faults, safety trips, deadline misses, or torque not confirmed off.</summary>
    public static int ExitCode(RunReport result)
    {
        ArgumentNullException.ThrowIfNull(result);
        if (result.Interrupted)
        {
            return Interrupted;
        }

        var clean = result.StoppedOnFault is null && result.DeadlineMisses == 0 && result.Faults.Count == 0 && result.Safety is not { Trips.Count: > 0 } && result.Stop?.TorqueOff != false;
        return clean ? 0 : 1;
    }

    /// <summary>Prints the fault that stopped the run and the stop's read-back (errors to <paramref name="error"/>).</summary>
    public static void Tell(RunReport result, TextWriter output, TextWriter error)
    {
        ArgumentNullException.ThrowIfNull(result);
        if (result.StoppedOnFault is { } fault)
        {
            error.WriteLine($"ROBOT FAULT: {fault}. The run stopped commanding and switched the motors off (--continue-on-fault to keep going).");
        }

        if (result.Interrupted)
        {
            error.WriteLine(string.Create(CultureInfo.InvariantCulture, $"interrupted after {result.DurationSeconds:F3} s"));
        }

        if (result.Scheduling is { } scheduling)
        {
            output.WriteLine($"  threads: {scheduling}");
        }

        if (result.Compiled is { } compiled)
        {
            output.WriteLine($"  compiled after start: {compiled.Summary}");
        }

        if (result.Stop is { } stop)
        {
            TellStop(stop, output, error);
        }
    }

    /// <summary>Prints what the modules said after the stop: torque off on all, or where it is not confirmed (to <paramref name="error"/>), and latched errors.</summary>
    public static void TellStop(StopCheck stop, TextWriter output, TextWriter error)
    {
        ArgumentNullException.ThrowIfNull(stop);
        var after = stop.AfterRequest is { } t ? string.Create(System.Globalization.CultureInfo.InvariantCulture, $", {t.TotalMilliseconds:0} ms after the stop request") : string.Empty;
        (stop.TorqueOff ? output : error).WriteLine($"  stop: {stop.Summary}{after}");
        if (stop.LoopHung is { } hung)
        {
            error.WriteLine($"  {hung}");
        }

        foreach (var latched in stop.LatchedErrors)
        {
            error.WriteLine($"  latched in module {latched}");
        }
    }
}
