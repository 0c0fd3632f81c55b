using System.Diagnostics;
using RobotControl.Kinematics.Geometry;
using RobotControl.Plugins.Touch.Backends;

namespace RobotControl.Plugins.Touch.OpenHaptics;

/// <summary>
/// A Geomagic Touch through the OpenHaptics HD API. <see cref="Open"/> joins the device to the process's 1 kHz
/// scheduler (<see cref="HdHost"/>) and waits for its first reading; <see cref="Exchange"/> hands the loop's force
/// to the servo callback and takes its latest reading, both through latest-value exchanges, so the loop never waits
/// on the device. A device error becomes a <see cref="TouchDeviceException"/> with the device's error text (the
/// plug-in faults, its outputs go to their safe values; the callback already sends zero force).
/// </summary>
internal sealed class OpenHapticsTouchBackend : ITouchBackend
{
    private static readonly TimeSpan FirstReadingTimeout = TimeSpan.FromSeconds(1);
    private readonly OpenHapticsOptions _options;
    private HdServo? _servo;
    private long _sequence;
    private ServoReading _reading;
    private long _frame = -1;
    private long _frameSeenAt = -1; // Stopwatch timestamp: the device's servo thread runs on the wall clock

    public OpenHapticsTouchBackend(OpenHapticsOptions options)
    {
        ArgumentNullException.ThrowIfNull(options);
        _options = options;
    }

    /// <inheritdoc />
    public string Description => _servo is { } s
        ? $"Geomagic Touch {_options.DeviceLabel} ({s.Info.Model}, serial {s.Info.Serial}, calibration {s.Info.CalibrationText}, force limit {s.MaxForceN:0.###} N)"
        : $"Geomagic Touch {_options.DeviceLabel} (OpenHaptics, not open)";

    /// <summary>The opened device (null before <see cref="Open"/>).</summary>
    internal HdServo? Servo => _servo;

    /// <inheritdoc />
    public void Open()
    {
        if (_servo is not null)
        {
            return;
        }

        _servo = HdHost.Join(_options);
        _sequence = 0;
        _frame = -1;
        _frameSeenAt = -1;
        var waited = System.Diagnostics.Stopwatch.StartNew();
        while (_servo.Readings.PublishedCount == 0)
        {
            if (waited.Elapsed > FirstReadingTimeout)
            {
                throw new TouchDeviceException($"'{_options.Instance}': the Touch {_options.DeviceLabel} gave no reading within {FirstReadingTimeout.TotalSeconds:0} s of starting the scheduler");
            }

            Thread.Sleep(1);
        }
    }

    /// <inheritdoc />
    public TouchSample Exchange(double timeSeconds, in TouchForce force)
    {
        var servo = _servo ?? throw new InvalidOperationException($"'{_options.Instance}': the Touch is not open");
        servo.Commands.Publish(new ServoCommand(force.XN, force.YN, force.ZN, force.Enabled, ++_sequence));
        servo.Readings.TryRead(out _reading);
        if (_reading.ErrorCode != HdConstants.Success)
        {
            throw new TouchDeviceException(Fault(_reading));
        }

        if (_reading.Frame != _frame || _frameSeenAt < 0)
        {
            _frame = _reading.Frame;
            _frameSeenAt = Stopwatch.GetTimestamp();
        }

        ReadOnlySpan<double> m = _reading.Transform;
        var rotation = new Rotation3d(new Vector3d(m[0], m[1], m[2]), new Vector3d(m[4], m[5], m[6]), new Vector3d(m[8], m[9], m[10]));
        var (roll, pitch, yaw) = rotation.ToRollPitchYaw();
        return new TouchSample(
            m[12],
            m[13],
            m[14],
            roll,
            pitch,
            yaw,
            (_reading.Buttons & HdConstants.Button1) != 0,
            (_reading.Buttons & HdConstants.Button2) != 0,
            Stopwatch.GetElapsedTime(_frameSeenAt).TotalMilliseconds); // wall time since the servo frame last changed (a virtual-clock run may be faster than the device)
    }

    /// <inheritdoc />
    public void Dispose()
    {
        if (_servo is { } servo)
        {
            _servo = null;
            HdHost.Leave(servo);
        }
    }

    private unsafe string Fault(in ServoReading reading) =>
        $"'{_options.Instance}': the Touch {_options.DeviceLabel} reported {HdNative.Describe(reading.ErrorCode, reading.InternalErrorCode, (byte*)reading.ErrorText)}";
}
