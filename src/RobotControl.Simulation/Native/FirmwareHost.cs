using System.Runtime.InteropServices;

namespace RobotControl.Simulation.Native;

/// <summary>P/Invoke surface of the firmware's host port, <c>librcfw_host.so</c> (firmware/ports/host/rcfw_host.h).</summary>
internal static unsafe partial class FirmwareHost
{
    public const string Library = "rcfw_host";
    public const int Ok = 0;
    public const int ErrorArgument = -1_000_000;
    public const int ErrorPower = -1_000_001;
    public const int MaxMotors = 4;
    public const int ControlRateHz = 10_000;
    public const int FramSize = 2048;

    public const byte ResetPowerOn = 1;
    public const byte ResetBrownOut = 2;
    public const byte ResetWatchdog = 3;
    public const byte ResetSoftware = 4;

    [LibraryImport(Library, EntryPoint = "rcfw_bus_create")]
    public static partial nint BusCreate(int modules, byte* ids, byte* motorsPerModule);

    [LibraryImport(Library, EntryPoint = "rcfw_bus_destroy")]
    public static partial void BusDestroy(nint bus);

    [LibraryImport(Library, EntryPoint = "rcfw_bus_set_baud")]
    public static partial int BusSetBaud(nint bus, uint bps);

    [LibraryImport(Library, EntryPoint = "rcfw_set_hall")]
    public static partial int SetHall(nint bus, int module, int motor, byte state);

    [LibraryImport(Library, EntryPoint = "rcfw_set_current_raw")]
    public static partial int SetCurrentRaw(nint bus, int module, int motor, ushort raw);

    [LibraryImport(Library, EntryPoint = "rcfw_set_pot_raw")]
    public static partial int SetPotRaw(nint bus, int module, int motor, ushort raw);

    [LibraryImport(Library, EntryPoint = "rcfw_advance_us")]
    public static partial int AdvanceUs(nint bus, uint us);

    [LibraryImport(Library, EntryPoint = "rcfw_bus_write")]
    public static partial int BusWrite(nint bus, byte* bytes, int length);

    [LibraryImport(Library, EntryPoint = "rcfw_bus_read")]
    public static partial int BusRead(nint bus, byte* buffer, int capacity);

    [LibraryImport(Library, EntryPoint = "rcfw_bus_pending")]
    public static partial int BusPending(nint bus);

    [LibraryImport(Library, EntryPoint = "rcfw_bus_collisions")]
    public static partial int BusCollisions(nint bus);

    [LibraryImport(Library, EntryPoint = "rcfw_get_pwm")]
    public static partial int GetPwm(nint bus, int module, int motor);

    [LibraryImport(Library, EntryPoint = "rcfw_get_driver_enable")]
    public static partial int GetDriverEnable(nint bus, int module, int motor);

    [LibraryImport(Library, EntryPoint = "rcfw_peek_table")]
    public static partial int PeekTable(nint bus, int module, ushort address, byte* buffer, int length);

    [LibraryImport(Library, EntryPoint = "rcfw_power_cycle")]
    public static partial int PowerCycle(nint bus, int module);

    [LibraryImport(Library, EntryPoint = "rcfw_power_off")]
    public static partial int PowerOff(nint bus, int module);

    [LibraryImport(Library, EntryPoint = "rcfw_fram_cut_after")]
    public static partial int FramCutAfter(nint bus, int module, int bytes);

    [LibraryImport(Library, EntryPoint = "rcfw_reset")]
    public static partial int Reset(nint bus, int module, byte cause);

    [LibraryImport(Library, EntryPoint = "rcfw_set_tx_broken")]
    public static partial int SetTransmitBroken(nint bus, int module, int broken);

    [LibraryImport(Library, EntryPoint = "rcfw_table_write")]
    public static partial int TableWrite(nint bus, int module, ushort address, byte* buffer, int length);

    /// <summary>Throws when a status-returning call failed.</summary>
    public static int Check(int status, string what) => status >= 0
        ? status
        : throw new InvalidOperationException($"{what} failed in the firmware host library: {(status == ErrorPower ? "module powered off" : status == ErrorArgument ? "bad argument" : status.ToString(System.Globalization.CultureInfo.InvariantCulture))}");
}
