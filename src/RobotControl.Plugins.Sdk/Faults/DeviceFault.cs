using System.Globalization;

namespace RobotControl.Plugins.Sdk.Faults;

/// <summary>The faults in an input device's data that a test harness can inject (<see cref="IFaultInjectable"/>).</summary>
public enum DeviceFaultKind
{
    /// <summary>The reading jumps along the device's x in one sample and stays offset (an encoder glitch, a stylus knocked).</summary>
    Jump,

    /// <summary>The device stops giving new readings: the last one repeats and its age grows (a cable pulled, a driver hung).</summary>
    Stale,
}

/// <summary>One fault to inject into a device: its kind and, for a jump, how far.</summary>
public sealed record DeviceFault
{
    private DeviceFault(DeviceFaultKind kind, double jumpXMm)
    {
        Kind = kind;
        JumpXMm = jumpXMm;
    }

    /// <summary>The device's readings stop (<see cref="DeviceFaultKind.Stale"/>).</summary>
    public static DeviceFault Stale { get; } = new(DeviceFaultKind.Stale, 0);

    /// <summary>What happens to the device's data.</summary>
    public DeviceFaultKind Kind { get; }

    /// <summary>For a <see cref="DeviceFaultKind.Jump"/>: how far the reading moves along x, mm (0 for other kinds).</summary>
    public double JumpXMm { get; }

    /// <summary>The reading jumps <paramref name="xMm"/> along x (<see cref="DeviceFaultKind.Jump"/>); the device that takes it refuses a distance that is not finite.</summary>
    public static DeviceFault Jump(double xMm) => new(DeviceFaultKind.Jump, xMm);

    /// <inheritdoc />
    public override string ToString() => Kind == DeviceFaultKind.Jump
        ? string.Create(CultureInfo.InvariantCulture, $"jump {JumpXMm:0.###} mm")
        : "stale";
}
