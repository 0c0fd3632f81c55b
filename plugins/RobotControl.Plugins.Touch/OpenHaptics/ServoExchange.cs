namespace RobotControl.Plugins.Touch.OpenHaptics;

/// <summary>What the control loop hands the servo callback each tick (through a latest-value exchange).</summary>
/// <param name="XN">Force along device x, N.</param>
/// <param name="YN">Force along device y, N.</param>
/// <param name="ZN">Force along device z, N.</param>
/// <param name="Enabled">The run level allows force.</param>
/// <param name="Sequence">Tick count of the loop (1 for the first tick); unchanged means the loop has stalled.</param>
internal readonly record struct ServoCommand(double XN, double YN, double ZN, bool Enabled, long Sequence);

/// <summary>What the servo callback hands the control loop each frame: one reading of the device, or its error.</summary>
internal struct ServoReading
{
    /// <summary>HD_CURRENT_TRANSFORM: 4×4, column-major, translation in mm.</summary>
    public Matrix16 Transform;

    /// <summary>HD_CURRENT_JOINT_ANGLES, rad.</summary>
    public Vector3 Joints;

    /// <summary>HD_CURRENT_GIMBAL_ANGLES, rad.</summary>
    public Vector3 Gimbal;

    /// <summary>HD_CURRENT_BUTTONS bit mask.</summary>
    public int Buttons;

    /// <summary>Frames since the device joined the scheduler.</summary>
    public long Frame;

    /// <summary>The ramp factor applied to the force of this frame (0: no force).</summary>
    public double ForceScale;

    /// <summary>The HD error of this frame, <see cref="HdConstants.Success"/> when none.</summary>
    public uint ErrorCode;

    /// <summary>The device's internal code of the error.</summary>
    public int InternalErrorCode;

    /// <summary>hdGetErrorString of the error (a static C string of the library).</summary>
    public nint ErrorText;

    /// <summary>Sixteen doubles inline (no allocation).</summary>
    [System.Runtime.CompilerServices.InlineArray(16)]
    public struct Matrix16
    {
        private double _element;
    }

    /// <summary>Three doubles inline.</summary>
    [System.Runtime.CompilerServices.InlineArray(3)]
    public struct Vector3
    {
        private double _element;
    }
}
