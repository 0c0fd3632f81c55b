using RobotControl.Definitions.Model;
using RobotControl.Modules;

namespace RobotControl.Robot.Bus;

/// <summary>
/// One motor-control module of the robot: its ID, friendly name and motors (named after their joints), and what the bus
/// thread last found out about it (presence, status, resets, watchdog), which any thread may read.
/// </summary>
[WrittenBy(RobotThread.Bus)]
public sealed class RobotController
{
    internal RobotController(ModuleDefinition definition, int index)
    {
        Definition = definition;
        Index = index;
    }

    /// <summary>The module's entry in the robot file.</summary>
    public ModuleDefinition Definition { get; }

    /// <summary>Bus ID.</summary>
    public byte Id => Definition.Id;

    /// <summary>Friendly name (its location), e.g. <c>right shoulder</c>.</summary>
    public string Name => Definition.Name;

    /// <summary>The module's motors in channel order.</summary>
    public IReadOnlyList<RobotMotor> Motors => MotorArray;

    /// <summary>The motors as an array (enumerated per cycle without allocating).</summary>
    internal RobotMotor[] MotorArray { get; set; } = [];

    /// <summary>True when the module answered discovery (and has not gone missing since).</summary>
    public bool Present => Volatile.Read(ref PresentFlag);

    /// <summary>Model number it reported.</summary>
    public ushort ModelNumber { get; internal set; }

    /// <summary>Firmware version it reported.</summary>
    public byte FirmwareVersion { get; internal set; }

    /// <summary>Latched hardware error bits last read (see the control table's hardware_error_status).</summary>
    public byte HardwareErrorStatus { get; internal set; }

    /// <summary>
    /// True when its status, as last read, shows a bus hold: after <c>bus_watchdog</c> ms without a frame it holds
    /// every motor where it was and refuses goals until the host acknowledges (<see cref="BusRobot.RequestHoldAcknowledgement"/>).
    /// </summary>
    public bool BusHold => ((HardwareErrors)HardwareErrorStatus).HasAny(HardwareErrors.BusHold);

    /// <summary>
    /// Its bus watchdog period (<c>bus_watchdog</c>, ms; 0: off) as last read back by the status poll, or -1 when not
    /// known: before the first poll, and from each time the host arms or disarms it until the next poll reads it back.
    /// </summary>
    public int BusWatchdogMs { get; internal set; } = -1;

    /// <summary>Times this module was seen to reset since the robot was opened.</summary>
    public int Resets { get; internal set; }

    /// <summary>
    /// The cause of its last reset (the control table's <c>reset_cause</c> code; 0: none seen): the one it reported
    /// when the host connected, or a later one seen while connected (see <see cref="LastResetBeforeConnect"/>).
    /// </summary>
    public int LastResetCause { get; internal set; }

    /// <summary>True when <see cref="LastResetCause"/> is the reset it reported at discovery, from before the host connected.</summary>
    public bool LastResetBeforeConnect { get; internal set; }

    /// <summary>Number of channels the bus exchange covers (highest channel + 1).</summary>
    internal int ChannelSpan => Definition.Motors.Count == 0 ? 1 : Definition.Motors.Max(m => m.Channel) + 1;

    internal int Index { get; }

    internal int ConsecutiveMisses { get; set; }

    /// <summary>Bus cycles in a row in which the module's feedback reply was missing or bad (0: it answered last cycle).</summary>
    public int MissedReplies => ConsecutiveMisses;

#pragma warning disable SA1401, CA1051 // written by the bus thread with Volatile
    internal bool PresentFlag;
#pragma warning restore SA1401, CA1051

    /// <inheritdoc />
    public override string ToString() => $"{Name} (id {Id})";
}
