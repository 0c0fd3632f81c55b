using System.Diagnostics;
using RobotControl.WebConsole.Adapter;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Tests.Adapter;

/// <summary>
/// The console writes a parameter through the robot layer's one parameter path (as <c>robotctl params set</c>): a
/// value the rules refuse never reaches the module, one the module refuses (motors on) is reported with its error, and
/// a valid one with the motors off is written and read back.
/// </summary>
public sealed class ParameterWriteTests
{
    [Fact]
    public async Task A_parameter_is_checked_then_written_and_read_back_with_the_motors_off()
    {
        using var session = ConsoleFixture.VirtualSession();
        var waited = Stopwatch.StartNew();
        while (!session.Status.TorqueOn)
        {
            Assert.True(waited.Elapsed < TimeSpan.FromSeconds(60), $"the motors never came on (run level {session.Status.RobotState})");
            await Task.Delay(50);
        }

        var kp = await Held(session, "kp");
        var limit = await Held(session, "current_limit");

        var locked = await session.WriteParameterAsync("right.elbow", "kp", kp + 1);
        Assert.Equal(CommandOutcome.Refused, locked.Outcome);
        Assert.StartsWith("right.elbow: P gain ", locked.Message, StringComparison.Ordinal);
        Assert.EndsWith("failed (Ok, 0x07 access error): the persistent area is locked while torque is on, turn torque off first", locked.Message, StringComparison.Ordinal);
        Assert.Equal(kp, await Held(session, "kp"));

        Assert.True((await session.TorqueAsync(false)).Succeeded);
        var refused = await session.WriteParameterAsync("right.elbow", "current_limit", 10);
        Assert.Equal(CommandOutcome.BadInput, refused.Outcome);
        Assert.Equal("right.elbow: current limit 10 A (163800 ADC raw): current_limit = 163800 is outside its range 0..4095 (u16, ADC raw); nothing was written", refused.Message);
        Assert.Equal(limit, await Held(session, "current_limit"));

        var written = await session.WriteParameterAsync("right.elbow", "kp", kp + 1);
        Assert.True(written.Succeeded, written.Message);
        Assert.Contains("written to FRAM (kp[0] = ", written.Message, StringComparison.Ordinal);
        Assert.EndsWith(", read back)", written.Message, StringComparison.Ordinal);
        Assert.Equal(kp + 1, await Held(session, "kp"), 0.05);
    }

    /// <summary>right.elbow's parameter as its module (2) holds it: read again, and published (a second command runs after the first one's publication).</summary>
    private static async Task<double> Held(LiveSession session, string key)
    {
        Assert.True((await session.ReloadParametersAsync(2)).Succeeded);
        Assert.True((await session.ReloadParametersAsync(2)).Succeeded);
        return session.Controllers.Single(c => c.Id == 2).Motors.Single(m => m.Name == "right.elbow").Parameters.Single(p => p.Key == key).Value;
    }
}
