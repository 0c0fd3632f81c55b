using RobotControl.Kinematics.Geometry;

namespace RobotControl.Plugins.Standard.Conditioning;

/// <summary>
/// The orthogonal map T = M R S from device axes to robot axes (S: axis inversions, R: roll-pitch-yaw rotation,
/// M: the mirror y -> -y) used by homing for motion and by the haptic walls to bring forces back to the device.
/// T may be improper (a reflection); orientations are mapped by conjugation, which always gives a rotation.
/// </summary>
internal readonly struct DeviceFrame
{
    private readonly Rotation3d _rotation;
    private readonly Vector3d _inversion;
    private readonly double _mirror;

    public DeviceFrame(double rollDeg, double pitchDeg, double yawDeg, bool invertX, bool invertY, bool invertZ, bool mirror)
    {
        const double deg = Math.PI / 180.0;
        _rotation = Rotation3d.FromRollPitchYaw(rollDeg * deg, pitchDeg * deg, yawDeg * deg);
        _inversion = new Vector3d(invertX ? -1 : 1, invertY ? -1 : 1, invertZ ? -1 : 1);
        _mirror = mirror ? -1 : 1;
    }

    /// <summary>Device vector to robot vector: M R S v.</summary>
    public Vector3d ToRobot(Vector3d device)
    {
        var r = _rotation.Apply(new Vector3d(device.X * _inversion.X, device.Y * _inversion.Y, device.Z * _inversion.Z));
        return new Vector3d(r.X, r.Y * _mirror, r.Z);
    }

    /// <summary>Robot vector to device vector: S R^T M v (T is orthogonal, so its inverse is its transpose).</summary>
    public Vector3d ToDevice(Vector3d robot)
    {
        var d = _rotation.ApplyTransposed(new Vector3d(robot.X, robot.Y * _mirror, robot.Z));
        return new Vector3d(d.X * _inversion.X, d.Y * _inversion.Y, d.Z * _inversion.Z);
    }

    /// <summary>A device orientation expressed in the robot frame: T Rd T^T.</summary>
    public Rotation3d ToRobot(Rotation3d device) =>
        new(ToRobot(Conjugate(device, Vector3d.UnitX)), ToRobot(Conjugate(device, Vector3d.UnitY)), ToRobot(Conjugate(device, Vector3d.UnitZ)));

    // Column j of T Rd T^T is T Rd (T^T e_j); returns Rd (T^T e_j) for ToRobot to finish.
    private Vector3d Conjugate(Rotation3d device, Vector3d robotAxis) => device.Apply(ToDevice(robotAxis));
}
