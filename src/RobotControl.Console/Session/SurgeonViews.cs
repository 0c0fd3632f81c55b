namespace RobotControl.WebConsole.Session;

/// <summary>What the surgeon's view shows besides the run level and the streamed signals.</summary>
/// <param name="Hands">One hand per arm that the graph drives, in robot-file order.</param>
/// <param name="Pedals">The foot-pedal outputs of the graph and what each drives.</param>
/// <param name="Faults">The supervisor's trips since the last reset, in plain words with their detail, oldest first.</param>
public sealed record SurgeonView(IReadOnlyList<HandView> Hands, IReadOnlyList<PedalView> Pedals, IReadOnlyList<FaultView> Faults);

/// <summary>One hand (the chain of plug-ins that drives one arm), found by plug-in type in the running graph.</summary>
/// <param name="Arm">Arm name.</param>
/// <param name="ClutchSignal">The clutch's <c>engaged</c> output (1 while held), or null without a clutch.</param>
/// <param name="LockSignal">The haptic lock's <c>locked</c> output, or null without one.</param>
/// <param name="Scaling">The scaling instance, or null without one.</param>
/// <param name="Scale">The ratio the scaling instance uses now (null without one).</param>
/// <param name="ScaleMin">Smallest ratio (the scaling setting's range).</param>
/// <param name="ScaleMax">Largest ratio.</param>
/// <param name="ScaleSettable">True when the console may set the ratio (its input is not wired in the graph).</param>
/// <param name="WallSignals">The haptic walls' force outputs <c>fx, fy, fz</c> (N, device frame), empty without walls.</param>
/// <param name="WallMaxForceN">The walls' per-axis force clamp (N), 0 without walls.</param>
/// <param name="ReachErrorSignal">The inverse kinematics' <c>error_mm</c> (how far the target lies past the reachable workspace), or null.</param>
public sealed record HandView(
    string Arm,
    string? ClutchSignal,
    string? LockSignal,
    string? Scaling,
    double? Scale,
    double ScaleMin,
    double ScaleMax,
    bool ScaleSettable,
    IReadOnlyList<string> WallSignals,
    double WallMaxForceN,
    string? ReachErrorSignal);

/// <summary>One foot-pedal output.</summary>
/// <param name="Signal">Its signal, e.g. <c>pedals.pedal1</c>.</param>
/// <param name="Drives">What it is wired to, in words (e.g. <c>run level (pedal)</c>, <c>right clutch</c>), or <c>nothing</c>.</param>
public sealed record PedalView(string Signal, string Drives);

/// <summary>One safety trip, in plain words and in detail.</summary>
/// <param name="TimeSeconds">When it tripped, session seconds.</param>
/// <param name="Words">What happened, for the surgeon, e.g. <c>left forearm module stopped answering — motors off</c>.</param>
/// <param name="Check">The supervisor's check, e.g. <c>module_silent</c>.</param>
/// <param name="Subject">The motor or module concerned (<c>left.forearm</c>), or empty.</param>
/// <param name="Arm">The arm it concerns (<c>left</c>), or empty when it concerns the whole robot (an E-STOP, a host stall).</param>
/// <param name="Measured">The value measured.</param>
/// <param name="Limit">The limit crossed.</param>
/// <param name="Unit">Unit of value and limit.</param>
/// <param name="Action">The safe state taken: <c>hold</c> or <c>torque_off</c>.</param>
public sealed record FaultView(double TimeSeconds, string Words, string Check, string Subject, string Arm, double Measured, double Limit, string Unit, string Action);

/// <summary>The reachable workspace of every arm, sampled once from the robot file's kinematics.</summary>
/// <param name="Arms">Arms in robot-file order.</param>
public sealed record WorkspaceView(IReadOnlyList<ArmWorkspaceView> Arms);

/// <summary>One arm's sampled workspace, in the URDF's <c>body</c> frame, metres, as flat x, y, z triples.</summary>
/// <param name="Arm">Arm name.</param>
/// <param name="ToolLink">The URDF link at the tool tip.</param>
/// <param name="Interior">Tool-tip positions with every joint within its limits.</param>
/// <param name="Walls">Tool-tip positions with one position joint at a limit (the workspace's walls).</param>
public sealed record ArmWorkspaceView(string Arm, string ToolLink, IReadOnlyList<double> Interior, IReadOnlyList<double> Walls);
