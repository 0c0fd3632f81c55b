using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.CoppeliaSim;

/// <summary>How the bridge moves the simulated joints.</summary>
public enum JointDriveMode
{
    /// <summary><c>sim.setJointPosition</c>: the joint is placed (kinematic joints, no physics).</summary>
    Kinematic,

    /// <summary><c>sim.setJointTargetPosition</c>: the joint's position controller is given the target (dynamic joints).</summary>
    Dynamic,
}

/// <summary>Settings of <see cref="CoppeliaSimPlugin"/>.</summary>
public sealed record CoppeliaSimSettings : PluginSettings
{
    /// <summary>The ZeroMQ remote API server (CoppeliaSim's <c>zmqRemoteApi.rpcPort</c>, 23000 by default).</summary>
    [Setting("ZeroMQ remote API endpoint of CoppeliaSim.", Required = true)]
    public string Endpoint { get; init; } = "tcp://127.0.0.1:23000";

    /// <summary>Path of the imported robot model in the scene.</summary>
    [Setting("Path of the robot model in the scene (the imported URDF's root), e.g. /LB1.", Required = true)]
    public string Model { get; init; } = "/LB1";

    /// <summary>Overrides of joint paths, <c>arm.joint=/path</c> comma-separated; the rest are <c>{model}/{arm}_{joint}</c>.</summary>
    [Setting("Joint path overrides, comma-separated arm.joint=/path (default for each joint: {model}/{arm}_{joint}, as robotctl urdf names them).")]
    public string JointPaths { get; init; } = "";

    /// <summary>Kinematic or dynamic joints.</summary>
    [Setting("kinematic: place the joints (sim.setJointPosition); dynamic: give their controllers targets (sim.setJointTargetPosition).")]
    public JointDriveMode Mode { get; init; } = JointDriveMode.Kinematic;

    /// <summary>Stepped mode: the simulation advances only when the bridge steps it.</summary>
    [Setting("Stepped simulation: CoppeliaSim advances one step every ticks_per_step loop ticks (sim.setStepping).")]
    public bool Stepping { get; init; }

    /// <summary>Loop ticks per simulation step in stepped mode.</summary>
    [Setting("Loop ticks per simulation step in stepped mode (e.g. 50 for CoppeliaSim's 50 ms step at 1 kHz).", Minimum = 1, Maximum = 100000)]
    public int TicksPerStep { get; init; } = 1;

    /// <summary>Deadline of every remote call.</summary>
    [Setting("Deadline of every remote call; a simulator silent for longer counts as lost.", Units = "ms", Minimum = 10, Maximum = 60000)]
    public int CallTimeoutMs { get; init; } = 500;
}
