using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;

namespace RobotControl.Plugins.Touch.OpenHaptics;

/// <summary>HDErrorInfo: the error code, the device's internal code and the device handle.</summary>
[StructLayout(LayoutKind.Sequential)]
internal readonly struct HdErrorInfo
{
    public readonly uint ErrorCode;
    public readonly int InternalErrorCode;
    public readonly uint Device;
}

/// <summary>
/// The HD API functions the back end calls. The library is found by <see cref="HdLibrary"/> (a DllImport resolver),
/// never by the default probing. HDAPIENTRY and HDCALLBACK are <c>__stdcall</c> in the headers (Windows and Linux;
/// only 32-bit x86 honours it, so Stdcall is right on every platform). HDSchedulerHandle and HDulong are C
/// <c>unsigned long</c>: 32 bits on Windows, 64 on Linux, hence <see cref="CULong"/>. HDboolean is unsigned char.
/// </summary>
internal static unsafe partial class HdNative
{
    public const string Library = "HD";

    [LibraryImport(Library, StringMarshalling = StringMarshalling.Utf8)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial uint hdInitDevice(string? name);

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial void hdDisableDevice(uint device);

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial void hdMakeCurrentDevice(uint device);

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial void hdBeginFrame(uint device);

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial void hdEndFrame(uint device);

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial void hdGetDoublev(uint parameter, double* values);

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial void hdGetIntegerv(uint parameter, int* values);

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial byte* hdGetString(uint parameter);

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial void hdSetDoublev(uint parameter, double* values);

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial void hdEnable(uint capability);

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial void hdDisable(uint capability);

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial uint hdCheckCalibration();

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial HdErrorInfo hdGetError();

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial byte* hdGetErrorString(uint error);

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial void hdStartScheduler();

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial void hdStopScheduler();

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial void hdSetSchedulerRate(CULong rateHz);

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial CULong hdScheduleAsynchronous(delegate* unmanaged[Stdcall]<nint, uint> callback, nint userData, ushort priority);

    [LibraryImport(Library)]
    [UnmanagedCallConv(CallConvs = [typeof(CallConvStdcall)])]
    public static partial void hdUnschedule(CULong handle);

    /// <summary>A C string from the library as text (empty for null).</summary>
    public static string Text(byte* text) => text is null ? "" : Marshal.PtrToStringUTF8((nint)text) ?? "";

    /// <summary>The text of the last error, or null when there is none (reads and clears it).</summary>
    public static string? TakeError()
    {
        var e = hdGetError();
        return e.ErrorCode == HdConstants.Success ? null : Describe(e.ErrorCode, e.InternalErrorCode, hdGetErrorString(e.ErrorCode));
    }

    /// <summary>One line for an error: the device's text, the HD code and the internal code.</summary>
    public static string Describe(uint code, int internalCode, byte* text) =>
        $"{Text(text)} (HD error 0x{code:X4}, internal {internalCode})";
}
