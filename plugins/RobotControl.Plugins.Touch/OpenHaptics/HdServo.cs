using RobotControl.Plugins.Sdk.Exchange;

namespace RobotControl.Plugins.Touch.OpenHaptics;

/// <summary>
/// One opened Touch and its part of the servo callback. The loop and the callback meet only in two latest-value
/// exchanges (<see cref="Commands"/> in, <see cref="Readings"/> out): neither ever waits for the other. A frame reads
/// the transform, joint and gimbal angles and buttons, sends the shaped force and checks hdGetError; the first error
/// latches: from then on the device gets zero force and the reading carries the error for the loop to fault on.
/// </summary>
internal sealed unsafe class HdServo
{
    private readonly uint _handle;
    private readonly bool _forceOutput;
    private readonly ForceShaper _shaper;
    private ServoReading _reading;
    private bool _faulted;

    private HdServo(OpenHapticsOptions options, uint handle, HdDeviceInfo info)
    {
        Options = options;
        _handle = handle;
        Info = info;
        _forceOutput = info.Calibrated;
        MaxForceN = Math.Min(options.MaxForceN, info.NominalMaxContinuousForceN);
        _shaper = new ForceShaper(MaxForceN, options.RampFrames, options.StaleFrames);
    }

    public OpenHapticsOptions Options { get; }

    public HdDeviceInfo Info { get; }

    /// <summary>The force limit in use: the configured one capped at the device's nominal continuous force.</summary>
    public double MaxForceN { get; }

    /// <summary>True when force output is enabled (only with calibration OK).</summary>
    public bool ForceOutput => _forceOutput;

    /// <summary>Loop to callback: the force to render.</summary>
    public LatestValue<ServoCommand> Commands { get; } = new();

    /// <summary>Callback to loop: the latest reading (or the error).</summary>
    public LatestValue<ServoReading> Readings { get; } = new();

    /// <summary>Opens the device (the scheduler must be stopped); enables force output only with calibration OK.</summary>
    /// <exception cref="TouchDeviceException">The device cannot be opened; the message has the device's error text.</exception>
    public static HdServo Open(OpenHapticsOptions options)
    {
        var handle = HdNative.hdInitDevice(options.DeviceName.Length == 0 ? null : options.DeviceName);
        if (handle == HdConstants.InvalidHandle)
        {
            throw new TouchDeviceException($"'{options.Instance}': cannot open the Touch {options.DeviceLabel}: {HdNative.TakeError() ?? "no error reported"}");
        }

        HdNative.hdMakeCurrentDevice(handle);
        var info = HdDeviceInfo.ReadCurrent(options.DeviceName);
        var servo = new HdServo(options, handle, info);
        if (servo._forceOutput)
        {
            HdNative.hdEnable(HdConstants.ForceOutput);
        }

        if (HdNative.TakeError() is { } error)
        {
            HdNative.hdDisableDevice(handle);
            throw new TouchDeviceException($"'{options.Instance}': the Touch {options.DeviceLabel} failed while opening: {error}");
        }

        return servo;
    }

    /// <summary>One servo frame (scheduler thread; allocation-free, never waits).</summary>
    public void Frame()
    {
        double* force = stackalloc double[3];
        new Span<double>(force, 3).Clear();
        HdNative.hdMakeCurrentDevice(_handle);
        HdNative.hdBeginFrame(_handle);
        if (_faulted)
        {
            if (_forceOutput)
            {
                HdNative.hdSetDoublev(HdConstants.CurrentForce, force);
            }

            HdNative.hdEndFrame(_handle);
            HdNative.hdGetError(); // drain: the first error is what the loop reports
            return;
        }

        double* transform = stackalloc double[16];
        double* joints = stackalloc double[3];
        double* gimbal = stackalloc double[3];
        var buttons = 0;
        HdNative.hdGetDoublev(HdConstants.CurrentTransform, transform);
        HdNative.hdGetDoublev(HdConstants.CurrentJointAngles, joints);
        HdNative.hdGetDoublev(HdConstants.CurrentGimbalAngles, gimbal);
        HdNative.hdGetIntegerv(HdConstants.CurrentButtons, &buttons);
        var haveCommand = Commands.TryRead(out var command);
        _shaper.Next(command, haveCommand, new Span<double>(force, 3));
        if (_forceOutput)
        {
            HdNative.hdSetDoublev(HdConstants.CurrentForce, force);
        }

        HdNative.hdEndFrame(_handle);
        var error = HdNative.hdGetError();
        new ReadOnlySpan<double>(transform, 16).CopyTo(_reading.Transform);
        new ReadOnlySpan<double>(joints, 3).CopyTo(_reading.Joints);
        new ReadOnlySpan<double>(gimbal, 3).CopyTo(_reading.Gimbal);
        _reading.Buttons = buttons;
        _reading.Frame++;
        _reading.ForceScale = _forceOutput ? _shaper.Scale : 0;
        if (error.ErrorCode != HdConstants.Success)
        {
            _faulted = true;
            _reading.ErrorCode = error.ErrorCode;
            _reading.InternalErrorCode = error.InternalErrorCode;
            _reading.ErrorText = (nint)HdNative.hdGetErrorString(error.ErrorCode);
            _reading.ForceScale = 0;
        }

        Readings.Publish(_reading);
    }

    /// <summary>Stops force output and releases the device (the scheduler must be stopped).</summary>
    public void Close()
    {
        HdNative.hdMakeCurrentDevice(_handle);
        if (_forceOutput)
        {
            HdNative.hdDisable(HdConstants.ForceOutput);
        }

        HdNative.hdDisableDevice(_handle);
        HdNative.hdGetError(); // a device that is gone may complain; it is closed either way
    }
}
