using System.Reflection;
using RobotControl.WebConsole.Adapter;

namespace RobotControl.WebConsole.Tests.Adapter;

/// <summary>
/// The console's bus thread runs its loop for the whole session with the watchdogs armed: it is compiled optimized
/// once, never replaced on the stack by a synchronous compile mid-session (as tier-0 code would be).
/// </summary>
public sealed class SessionLoopCodeTests
{
    [Fact]
    public void The_real_bus_session_loop_skips_tiered_compilation()
    {
        var loop = typeof(HeadlessSession).GetMethod("RunRealTime", BindingFlags.Instance | BindingFlags.NonPublic);

        Assert.NotNull(loop);
        Assert.True(loop.MethodImplementationFlags.HasFlag(MethodImplAttributes.AggressiveOptimization));
    }
}
