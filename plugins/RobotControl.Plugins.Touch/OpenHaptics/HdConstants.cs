namespace RobotControl.Plugins.Touch.OpenHaptics;

/// <summary>
/// The OpenHaptics HD API values the back end uses, as published in <c>HD/hdDefines.h</c> and <c>HD/hdScheduler.h</c>
/// (OpenHaptics 3.0 and 3.3 copies agree; docs/touch.md records the cross-check).
/// </summary>
internal static class HdConstants
{
    // Error codes (HDerror).
    public const uint Success = 0x0000;
    public const uint ExceededMaxForce = 0x0201;
    public const uint DeviceFault = 0x0300;
    public const uint CommError = 0x0302;

    // Get / set parameters (HDenum).
    public const uint CurrentButtons = 0x2000;
    public const uint CurrentTransform = 0x2052;
    public const uint CurrentJointAngles = 0x2100;
    public const uint CurrentGimbalAngles = 0x2150;
    public const uint DeviceModelType = 0x2501;
    public const uint DeviceSerialNumber = 0x2504;
    public const uint NominalMaxForce = 0x2603;
    public const uint NominalMaxContinuousForce = 0x2604;
    public const uint CurrentForce = 0x2700;

    // Capabilities for hdEnable / hdDisable.
    public const uint ForceOutput = 0x4000;

    // hdCheckCalibration results.
    public const uint CalibrationOk = 0x5000;
    public const uint CalibrationNeedsUpdate = 0x5001;
    public const uint CalibrationNeedsManualInput = 0x5002;

    // Button masks of HD_CURRENT_BUTTONS.
    public const int Button1 = 1 << 0;
    public const int Button2 = 1 << 1;

    /// <summary>HD_INVALID_HANDLE, what hdInitDevice returns on failure.</summary>
    public const uint InvalidHandle = 0xFFFFFFFF;

    /// <summary>HD_MAX_SCHEDULER_PRIORITY (USHRT_MAX).</summary>
    public const ushort MaxSchedulerPriority = ushort.MaxValue;

    /// <summary>HD_CALLBACK_CONTINUE: keep the asynchronous callback scheduled.</summary>
    public const uint CallbackContinue = 1;

    /// <summary>The servo rate the back end asks for, Hz.</summary>
    public const uint ServoRateHz = 1000;

    /// <summary>A calibration state as text.</summary>
    public static string CalibrationText(uint state) => state switch
    {
        CalibrationOk => "ok",
        CalibrationNeedsUpdate => "needs update (put the stylus in the inkwell)",
        CalibrationNeedsManualInput => "needs manual input (run Touch Setup / Touch Diagnostic)",
        _ => $"unknown (0x{state:X4})",
    };
}
