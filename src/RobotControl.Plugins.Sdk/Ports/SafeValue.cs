namespace RobotControl.Plugins.Sdk.Ports;

/// <summary>What an output shows when its plug-in faults or produces a non-finite value.</summary>
public enum SafeValue
{
    /// <summary>Keep the last finite value (positions, setpoints: "stay where you are").</summary>
    HoldLastFinite,

    /// <summary>Zero (forces, velocities: "stop pushing").</summary>
    Zero,

    /// <summary>
    /// The port's initial value (an age: "never heard from", so that a faulted receiver reads as stale rather than as
    /// fresh as it last was).
    /// </summary>
    Initial,
}
