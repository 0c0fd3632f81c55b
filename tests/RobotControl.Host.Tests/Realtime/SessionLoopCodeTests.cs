using System.Reflection;
using RobotControl.Robot.Bus;
using RobotControl.Runtime.Loop;
using RobotControl.Simulation;

namespace RobotControl.Host.Tests.Realtime;

/// <summary>
/// The loops that run for a whole session on a real-time thread are compiled optimized once, before they start. As
/// quick (tier-0) code they were replaced on the stack after a few seconds by a synchronous compile on that very
/// thread: 17–23 ms in the simulator's serving loop (every run tripped at start), 14 ms in the control loop.
/// </summary>
public sealed class SessionLoopCodeTests
{
    public static TheoryData<Type, string> Loops => new()
    {
        { typeof(ControlLoop), "ThreadMain" },
        { typeof(BusRobot).Assembly.GetType("RobotControl.Robot.Bus.BusThread", throwOnError: true)!, "Loop" },
        { typeof(VirtualRobot), nameof(VirtualRobot.Serve) },
    };

    [Theory]
    [MemberData(nameof(Loops))]
    public void A_loop_that_runs_for_the_whole_session_skips_tiered_compilation(Type type, string method)
    {
        var m = type.GetMethods(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic).Single(x => x.Name == method);

        Assert.True(m.MethodImplementationFlags.HasFlag(MethodImplAttributes.AggressiveOptimization), $"{type.Name}.{method}");
    }
}
