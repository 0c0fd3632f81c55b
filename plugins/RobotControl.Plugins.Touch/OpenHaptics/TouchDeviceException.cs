namespace RobotControl.Plugins.Touch.OpenHaptics;

/// <summary>The HD library or a Touch device failed; the message is one line naming the device and the device's error text.</summary>
public sealed class TouchDeviceException : InvalidOperationException
{
    /// <summary>Creates the exception.</summary>
    public TouchDeviceException()
    {
    }

    /// <summary>Creates the exception with a message.</summary>
    public TouchDeviceException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with a message and a cause.</summary>
    public TouchDeviceException(string message, Exception innerException)
        : base(message, innerException)
    {
    }
}
