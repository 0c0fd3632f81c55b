using RobotControl.Host.Session;

namespace RobotControl.Host.Tests.Safety;

public sealed class StepCapTests
{
    [Fact]
    public void A_setpoint_jump_reaches_the_modules_only_as_steps_of_maximum_speed_times_period_and_is_counted()
    {
        var goal = RobotControl.Bus.Protocol.ControlTable.Firmware["goal_position"];
        GoalFrameSpy? spy = null;
        using var session = RobotSession.Open(
            new SessionOptions { GraphPath = Graphs.Path("teleop-lb.json"), WrapLink = (link, clock) => spy = new GoalFrameSpy(link, clock, goal.At(0), goal.Stride) },
            TestPlugins.Catalog());
        session.Supervisor.PedalDown("pedal");
        var robot = session.Robot;
        var far = robot.Definition.Joints.Select(j => j.MaxRad).ToArray(); // every joint to its upper limit at once
        var start = spy!.Frames.Count;
        session.RunVirtual(100, null, (loop, _) =>
        {
            loop.Step();
            robot.WriteJointSetpoints(0, far);
        });

        Assert.True(robot.StepCapHits > 10, $"cap hits {robot.StepCapHits}");
        var worst = spy.WorstStepOverCap(robot.Motors.Select(m => (m.Config.ModuleId, m.Config.Channel, m.Config.CountsPerRad, m.SpeedLimitRadS)), start);
        Assert.InRange(worst, 0.5, 1); // the cap was reached, never exceeded
        Assert.True(robot.LargestCappedStepRad > 0.1);
    }
}
