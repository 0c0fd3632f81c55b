namespace RobotControl.Robot.Bus;

/// <summary>Which modules take part in the cycles (<see cref="ActiveModules"/>), rebuilt by the bus thread when that changes.</summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class ModuleRoster(RobotLayout layout)
{
    private volatile ActiveModules _active = ActiveModules.None;

    /// <summary>The present modules and the cycle's buffers for them.</summary>
    public ActiveModules Active => _active;

    /// <summary>Takes the controllers' presence as it is now (after discovery, or a module found again).</summary>
    public void Rebuild() => _active = new ActiveModules(layout);
}
