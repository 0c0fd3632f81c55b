using RobotControl.Kinematics.Geometry;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;

namespace RobotControl.Plugins.Standard.Conditioning;

/// <summary>
/// Homing: gives the input device a new base frame, p_robot = origin + T (p_device - device_home), with T a rotation,
/// optional axis inversions and, for the left arm, the mirror y -> -y, so both arms share one kinematic model.
/// Orientation (roll, pitch, yaw) is mapped into the same frame.
/// </summary>
[PluginType("homing", Description = "Device frame to robot frame: rigid transform, axis inversion, left-arm mirror.")]
public sealed class HomingPlugin : Plugin<HomingSettings>
{
    private readonly InputPort _x;
    private readonly InputPort _y;
    private readonly InputPort _z;
    private readonly InputPort _roll;
    private readonly InputPort _pitch;
    private readonly InputPort _yaw;
    private readonly OutputPort _outX;
    private readonly OutputPort _outY;
    private readonly OutputPort _outZ;
    private readonly OutputPort _outRoll;
    private readonly OutputPort _outPitch;
    private readonly OutputPort _outYaw;
    private readonly DeviceFrame _frame;
    private readonly Vector3d _origin;
    private readonly Vector3d _deviceHome;

    /// <summary>Creates the plug-in.</summary>
    public HomingPlugin(HomingSettings settings, PluginContext context)
        : base(settings, context)
    {
        var s = Settings;
        _frame = new DeviceFrame(s.RollDeg, s.PitchDeg, s.YawDeg, s.InvertX, s.InvertY, s.InvertZ, s.Mirror);
        _origin = new Vector3d(s.OriginXMm, s.OriginYMm, s.OriginZMm);
        _deviceHome = new Vector3d(s.DeviceHomeXMm, s.DeviceHomeYMm, s.DeviceHomeZMm);
        _x = DeclareInput("x", "mm", "device x");
        _y = DeclareInput("y", "mm", "device y");
        _z = DeclareInput("z", "mm", "device z");
        _roll = DeclareInput("roll", "rad", "device roll");
        _pitch = DeclareInput("pitch", "rad", "device pitch");
        _yaw = DeclareInput("yaw", "rad", "device yaw");
        _outX = DeclareOutput("x", SafeValue.HoldLastFinite, "mm", "robot-frame x", _origin.X);
        _outY = DeclareOutput("y", SafeValue.HoldLastFinite, "mm", "robot-frame y", _origin.Y);
        _outZ = DeclareOutput("z", SafeValue.HoldLastFinite, "mm", "robot-frame z", _origin.Z);
        _outRoll = DeclareOutput("roll", SafeValue.HoldLastFinite, "rad", "robot-frame roll");
        _outPitch = DeclareOutput("pitch", SafeValue.HoldLastFinite, "rad", "robot-frame pitch");
        _outYaw = DeclareOutput("yaw", SafeValue.HoldLastFinite, "rad", "robot-frame yaw");
    }

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        var device = new Vector3d(Read(_x), Read(_y), Read(_z));
        var p = _origin + _frame.ToRobot(device - _deviceHome);
        Write(_outX, p.X);
        Write(_outY, p.Y);
        Write(_outZ, p.Z);
        var r = _frame.ToRobot(Rotation3d.FromRollPitchYaw(Read(_roll), Read(_pitch), Read(_yaw)));
        var (roll, pitch, yaw) = r.ToRollPitchYaw();
        Write(_outRoll, roll);
        Write(_outPitch, pitch);
        Write(_outYaw, yaw);
    }
}
