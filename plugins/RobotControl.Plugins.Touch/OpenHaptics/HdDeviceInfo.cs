namespace RobotControl.Plugins.Touch.OpenHaptics;

/// <summary>What a Touch device says about itself once opened.</summary>
/// <param name="Name">The name it was opened by (empty: the default device).</param>
/// <param name="Model">HD_DEVICE_MODEL_TYPE.</param>
/// <param name="Serial">HD_DEVICE_SERIAL_NUMBER.</param>
/// <param name="Calibration">hdCheckCalibration's result (HD_CALIBRATION_*).</param>
/// <param name="NominalMaxForceN">HD_NOMINAL_MAX_FORCE, N.</param>
/// <param name="NominalMaxContinuousForceN">HD_NOMINAL_MAX_CONTINUOUS_FORCE, N.</param>
public sealed record HdDeviceInfo(string Name, string Model, string Serial, uint Calibration, double NominalMaxForceN, double NominalMaxContinuousForceN)
{
    /// <summary>True when the calibration is HD_CALIBRATION_OK.</summary>
    public bool Calibrated => Calibration == HdConstants.CalibrationOk;

    /// <summary>The calibration state as text.</summary>
    public string CalibrationText => HdConstants.CalibrationText(Calibration);

    /// <summary>Reads the current device's identity, calibration and force limits (not on the servo thread).</summary>
    internal static unsafe HdDeviceInfo ReadCurrent(string name)
    {
        double peak = 0, continuous = 0;
        HdNative.hdGetDoublev(HdConstants.NominalMaxForce, &peak);
        HdNative.hdGetDoublev(HdConstants.NominalMaxContinuousForce, &continuous);
        return new HdDeviceInfo(
            name,
            HdNative.Text(HdNative.hdGetString(HdConstants.DeviceModelType)).Trim(),
            HdNative.Text(HdNative.hdGetString(HdConstants.DeviceSerialNumber)).Trim(),
            HdNative.hdCheckCalibration(),
            peak,
            continuous);
    }
}
