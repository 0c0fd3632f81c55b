using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;

namespace RobotControl.Plugins.Touch.OpenHaptics;

/// <summary>
/// The process's one OpenHaptics scheduler and the devices on it. Devices are opened only while the scheduler is
/// stopped (the HD API's order: init devices, enable force, schedule, start), so a device joining or leaving stops
/// the scheduler, changes the device list and starts it again. One asynchronous callback at
/// HD_MAX_SCHEDULER_PRIORITY and 1 kHz runs a frame of every device and returns HD_CALLBACK_CONTINUE.
/// </summary>
internal static unsafe class HdHost
{
    private static readonly Lock Gate = new();
    private static HdServo[] _servos = [];
    private static CULong _callback;
    private static bool _running;

    /// <summary>Loads the library and opens the device of <paramref name="options"/> onto the running scheduler.</summary>
    /// <exception cref="TouchDeviceException">No library, the device is in use or cannot be opened, or the scheduler fails.</exception>
    public static HdServo Join(OpenHapticsOptions options)
    {
        ArgumentNullException.ThrowIfNull(options);
        lock (Gate)
        {
            HdLibrary.Load(options.LibraryPath);
            if (Array.Find(_servos, s => s.Options.DeviceName == options.DeviceName) is { } other)
            {
                throw new TouchDeviceException($"'{options.Instance}': the Touch {options.DeviceLabel} is already used by '{other.Options.Instance}' (one instance per device)");
            }

            StopScheduler();
            try
            {
                var servo = HdServo.Open(options);
                Volatile.Write(ref _servos, [.. _servos, servo]);
                return servo;
            }
            finally
            {
                StartScheduler();
            }
        }
    }

    /// <summary>Takes a device off the scheduler and closes it; the scheduler keeps running for the others.</summary>
    public static void Leave(HdServo servo)
    {
        ArgumentNullException.ThrowIfNull(servo);
        lock (Gate)
        {
            StopScheduler();
            Volatile.Write(ref _servos, Array.FindAll(_servos, s => !ReferenceEquals(s, servo)));
            servo.Close();
            StartScheduler();
        }
    }

    private static void StopScheduler()
    {
        if (_running)
        {
            HdNative.hdStopScheduler();
            HdNative.hdUnschedule(_callback);
            HdNative.hdGetError();
            _running = false;
        }
    }

    private static void StartScheduler()
    {
        if (_servos.Length == 0)
        {
            return;
        }

        HdNative.hdSetSchedulerRate(new CULong(HdConstants.ServoRateHz));
        _callback = HdNative.hdScheduleAsynchronous(&Servo, 0, HdConstants.MaxSchedulerPriority);
        HdNative.hdStartScheduler();
        _running = true;
        if (HdNative.TakeError() is { } error)
        {
            StopScheduler();
            throw new TouchDeviceException($"the OpenHaptics scheduler failed to start: {error}");
        }
    }

    [UnmanagedCallersOnly(CallConvs = [typeof(CallConvStdcall)])]
    private static uint Servo(nint userData)
    {
        foreach (var servo in Volatile.Read(ref _servos))
        {
            servo.Frame();
        }

        return HdConstants.CallbackContinue;
    }
}
