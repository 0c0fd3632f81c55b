namespace RobotControl.WebConsole.Session;

/// <summary>The session at a glance.</summary>
/// <param name="Robot">Robot design name.</param>
/// <param name="Graph">Graph file name.</param>
/// <param name="Transport">The bus transport (e.g. <c>virtual</c>, <c>serial:/dev/ttyUSB0?baud=1000000</c>).</param>
/// <param name="ModulesConfigured">Modules the robot file lists.</param>
/// <param name="ModulesFound">Modules that answered discovery.</param>
/// <param name="LoopRateHz">Nominal loop rate.</param>
/// <param name="Ticks">Loop ticks so far.</param>
/// <param name="DeadlineMisses">Deadline misses so far.</param>
/// <param name="TickMedianUs">Median tick time, microseconds.</param>
/// <param name="TickP99Us">99th-percentile tick time, microseconds.</param>
/// <param name="TickMaxUs">Longest tick, microseconds.</param>
/// <param name="TickAllocatedBytes">Bytes the loop's ticks (loop and ring recorder) allocated since the start, counted on a virtual session's thread; null on a real bus.</param>
/// <param name="SessionSeconds">Session (loop clock) time so far.</param>
/// <param name="RobotState">The safety supervisor's run level: E_STOP, INIT, HOMING, PEDAL_UP or PEDAL_DOWN.</param>
/// <param name="RobotLayer">The robot layer's state (Disabled, Discovered, Homing, Homed, Enabled, Fault).</param>
/// <param name="Session">The console's session thread: running (or holding, when a plug-in faulted), stopped or failed.</param>
/// <param name="TorqueOn">True while the motors are driven.</param>
/// <param name="Faults">The robot's fault flags by name and the supervisor's trips (empty when healthy).</param>
/// <param name="PluginFaults">Plug-in faults of the graph.</param>
/// <param name="Bus">Bus counters.</param>
public sealed record SessionStatus(
    string Robot,
    string Graph,
    string Transport,
    int ModulesConfigured,
    int ModulesFound,
    double LoopRateHz,
    long Ticks,
    long DeadlineMisses,
    double TickMedianUs,
    double TickP99Us,
    double TickMaxUs,
    long? TickAllocatedBytes,
    double SessionSeconds,
    string RobotState,
    string RobotLayer,
    string Session,
    bool TorqueOn,
    IReadOnlyList<string> Faults,
    int PluginFaults,
    BusCounters Bus);

/// <summary>Bus counters summed over the modules.</summary>
/// <param name="Cycles">Bus cycles run.</param>
/// <param name="Frames">Frames sent and received.</param>
/// <param name="CrcErrors">Frames dropped for a bad CRC.</param>
/// <param name="Timeouts">Replies that did not come.</param>
/// <param name="Retries">Transactions retried.</param>
public sealed record BusCounters(long Cycles, long Frames, long CrcErrors, long Timeouts, long Retries);

/// <summary>One controller (motor-control module).</summary>
/// <param name="Id">Bus ID.</param>
/// <param name="Name">Friendly name.</param>
/// <param name="Present">True when it answered discovery.</param>
/// <param name="MissedReplies">Polls in a row it has not answered (0: it answered the last); above 0 the values shown are the last it gave.</param>
/// <param name="Model">Model number it reported.</param>
/// <param name="Firmware">Firmware version it reported.</param>
/// <param name="ResetCause">Why it last reset, in words.</param>
/// <param name="Resets">Resets seen in this session.</param>
/// <param name="Watchdog">Bus watchdog period in ms (0: off) and whether it tripped.</param>
/// <param name="HardwareErrors">Latched hardware error bits by name (empty when none).</param>
/// <param name="Motors">Its motors in channel order.</param>
public sealed record ControllerView(
    int Id,
    string Name,
    bool Present,
    int MissedReplies,
    int Model,
    int Firmware,
    string ResetCause,
    int Resets,
    string Watchdog,
    IReadOnlyList<string> HardwareErrors,
    IReadOnlyList<MotorView> Motors);

/// <summary>One motor.</summary>
/// <param name="Name">Unique name, <c>arm.joint</c>.</param>
/// <param name="Joint">Joint (or tool drive) it drives.</param>
/// <param name="Channel">Channel on its module.</param>
/// <param name="PositionDeg">Latest axis output angle, degrees.</param>
/// <param name="MinDeg">Smallest setpoint the joint limits allow, degrees.</param>
/// <param name="MaxDeg">Largest setpoint the joint limits allow, degrees.</param>
/// <param name="CurrentA">Latest filtered current, A.</param>
/// <param name="Pwm">Latest PWM (-255..255).</param>
/// <param name="Manual">True while jogged or set by hand.</param>
/// <param name="TorqueOn">True while driven.</param>
/// <param name="Errors">Latched motor error bits by name.</param>
/// <param name="Parameters">Its persistent parameters as the module holds them.</param>
/// <param name="DesiredDeg">The goal it follows, degrees: the goal last sent to it (its jog or setpoint target while manual, else the control loop's, under the step cap and any hold).</param>
/// <param name="LoopCommandDeg">The goal the control loop's setpoints ask of it (the graph's command through the couplings), degrees: where a release hands it back to.</param>
/// <param name="SpeedLimitDegS">Its speed limit at the axis output, degrees per second: how fast a goal moves under the step cap (a release's move takes the distance over this).</param>
/// <param name="DesiredSignal">The ring signal of <paramref name="DesiredDeg"/> (radians), to plot it.</param>
/// <param name="MeasuredSignal">The ring signal of its measured axis output (radians), to plot it.</param>
public sealed record MotorView(
    string Name,
    string Joint,
    int Channel,
    double PositionDeg,
    double MinDeg,
    double MaxDeg,
    double CurrentA,
    int Pwm,
    bool Manual,
    bool TorqueOn,
    IReadOnlyList<string> Errors,
    IReadOnlyList<ParameterSpec> Parameters,
    double DesiredDeg,
    double LoopCommandDeg,
    double SpeedLimitDegS,
    string DesiredSignal,
    string MeasuredSignal);

/// <summary>One editable parameter of a motor.</summary>
/// <param name="Key">Its key in the API.</param>
/// <param name="Label">What it is.</param>
/// <param name="Unit">Its unit.</param>
/// <param name="Value">The value the module holds (NaN: not read).</param>
/// <param name="FileValue">The value the robot file gives.</param>
/// <param name="Min">Smallest value the console accepts.</param>
/// <param name="Max">Largest value the console accepts (the module may refuse less).</param>
public sealed record ParameterSpec(string Key, string Label, string Unit, double Value, double FileValue, double Min, double Max);

/// <summary>One entry of the event log.</summary>
/// <param name="Sequence">Increasing number.</param>
/// <param name="TimeSeconds">Session time.</param>
/// <param name="Source">Who reported it.</param>
/// <param name="Message">What happened.</param>
public sealed record EventEntry(long Sequence, double TimeSeconds, string Source, string Message);

/// <summary>Timing of one component.</summary>
/// <param name="Component">Its name.</param>
/// <param name="Count">Runs measured.</param>
/// <param name="MedianUs">Median run time, microseconds.</param>
/// <param name="P99Us">99th-percentile run time, microseconds.</param>
/// <param name="MaxUs">Longest run, microseconds.</param>
public sealed record ComponentTiming(string Component, long Count, double MedianUs, double P99Us, double MaxUs);

/// <summary>The 3D view's model: the robot's URDF (both arms, as the host's exporter writes it) and each arm's joints and signals.</summary>
/// <param name="Urdf">URDF document of the robot (<c>robotctl urdf</c>), lengths in metres.</param>
/// <param name="Arms">Arms in robot-file order.</param>
public sealed record RobotModelView(string Urdf, IReadOnlyList<ArmView> Arms);

/// <summary>One arm of the 3D view.</summary>
/// <param name="Name">Arm name.</param>
/// <param name="Joints">URDF joint names of its joints, in the robot file's joint order.</param>
/// <param name="PositionSignals">Ring signals of its measured joints, in joint order.</param>
/// <param name="CommandSignals">Ring signals of its commanded joints, in joint order.</param>
public sealed record ArmView(string Name, IReadOnlyList<string> Joints, IReadOnlyList<string> PositionSignals, IReadOnlyList<string> CommandSignals);
