using RobotControl.Host.Session;
using RobotControl.Robot.States;

namespace RobotControl.Host.Tests.Session;

public sealed class RobotSessionTests
{
    private static double[] RunVirtual(long ticks)
    {
        using var session = RobotSession.Open(new SessionOptions { GraphPath = Graphs.Path("teleop-lb.json") }, TestPlugins.Catalog());
        Assert.True(session.IsVirtual);
        Assert.Equal(RobotState.Enabled, session.Robot.State);
        Assert.True(session.Discovery.AllAsConfigured);
        var cycles = 0L;
        session.RunVirtual(ticks, () => cycles++);
        Assert.Equal(ticks, session.Loop.TickCount);
        Assert.Equal(cycles, session.Robot.Cycles);
        var q = new double[session.Robot.Definition.JointCount * session.Robot.ArmCount];
        for (var arm = 0; arm < session.Robot.ArmCount; arm++)
        {
            session.Robot.ReadJointPositions(arm, q.AsSpan(arm * session.Robot.Definition.JointCount, session.Robot.Definition.JointCount));
        }

        return q;
    }

    [Fact]
    public void A_virtual_session_comes_up_enabled_runs_its_ticks_and_is_deterministic()
    {
        var first = RunVirtual(300);
        var second = RunVirtual(300);
        Assert.Equal(first, second);
    }

    [Fact]
    public void A_virtual_session_refuses_to_start_real_threads()
    {
        using var session = RobotSession.Open(new SessionOptions { GraphPath = Graphs.Path("teleop-lb.json") }, TestPlugins.Catalog());
        Assert.Throws<InvalidOperationException>(() => session.StartRealtime());
    }

    [Fact]
    public void The_shipped_plug_ins_are_registered_in_one_place()
    {
        var catalog = TestPlugins.Catalog();
        Assert.Contains(catalog.Types, t => t.Name == "clutch");
        Assert.Contains(catalog.Types, t => t.Name == "touch");
    }
}
