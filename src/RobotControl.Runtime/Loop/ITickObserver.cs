using RobotControl.Plugins.Sdk;

namespace RobotControl.Runtime.Loop;

/// <summary>Called on the loop thread after every tick, outside the timed section (measurement, progress).</summary>
public interface ITickObserver
{
    /// <summary>The tick that just ran. Must not block or allocate.</summary>
    void AfterTick(in TickContext context);
}
