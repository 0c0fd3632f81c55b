using RobotControl.Kinematics.Geometry;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Settings;
using RobotControl.Plugins.Standard.Conditioning;

namespace RobotControl.Plugins.Standard.Haptics;

/// <summary>
/// Haptic workspace walls: takes the IK's workspace force k_s (Ph - Pd) (arm base frame; zero while reachable) and
/// renders it on the device: undoes homing (rotation, inversions, mirror) and scaling (a device displacement is the
/// robot displacement over the ratio), applies the gain and the per-axis sign settings, and clamps each axis. The
/// result pushes the handle toward the reachable point. The ratio is the input <c>scale_ratio</c>, starting at the
/// setting of that name; graphs wire the arm's scaling <c>ratio</c> output to it, so that a ratio changed while the
/// clutch is held changes the wall's stiffness on the device with it. A ratio outside the setting's range (or not
/// finite) is ignored and the last good one kept.
/// </summary>
[PluginType("haptic_walls", Description = "Workspace force from the IK, expressed in the device frame and clamped.")]
public sealed class HapticWallsPlugin : Plugin<HapticWallsSettings>
{
    private readonly InputPort _fx;
    private readonly InputPort _fy;
    private readonly InputPort _fz;
    private readonly OutputPort _outX;
    private readonly OutputPort _outY;
    private readonly OutputPort _outZ;
    private readonly DeviceFrame _frame;
    private static readonly SettingDescriptor RatioSetting = SettingsSchema.For(typeof(HapticWallsSettings)).Find("scale_ratio")!;

    private readonly InputPort _ratio;
    private readonly Vector3d _sign;
    private double _scale;

    /// <summary>Creates the plug-in.</summary>
    public HapticWallsPlugin(HapticWallsSettings settings, PluginContext context)
        : base(settings, context)
    {
        var s = Settings;
        _frame = new DeviceFrame(s.RollDeg, s.PitchDeg, s.YawDeg, s.InvertX, s.InvertY, s.InvertZ, s.Mirror);
        _sign = new Vector3d(s.InvertForceX ? -1 : 1, s.InvertForceY ? -1 : 1, s.InvertForceZ ? -1 : 1);
        _scale = s.Gain / s.ScaleRatio;
        _fx = DeclareInput("fx", "N", "workspace force x (arm base frame)");
        _fy = DeclareInput("fy", "N", "workspace force y");
        _fz = DeclareInput("fz", "N", "workspace force z");
        _ratio = DeclareInput("scale_ratio", "", $"the arm's motion ratio ({RatioSetting.Minimum}..{RatioSetting.Maximum}; starts at the scale_ratio setting)", s.ScaleRatio);
        _outX = DeclareOutput("fx", SafeValue.Zero, "N", "wall force along device x");
        _outY = DeclareOutput("fy", SafeValue.Zero, "N", "wall force along device y");
        _outZ = DeclareOutput("fz", SafeValue.Zero, "N", "wall force along device z");
    }

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        var ratio = Read(_ratio);
        if (RatioSetting.Accepts(ratio))
        {
            _scale = Settings.Gain / ratio;
        }

        var device = _frame.ToDevice(new Vector3d(Read(_fx), Read(_fy), Read(_fz))) * _scale;
        var max = Settings.MaxForceN;
        Write(_outX, Math.Clamp(device.X * _sign.X, -max, max));
        Write(_outY, Math.Clamp(device.Y * _sign.Y, -max, max));
        Write(_outZ, Math.Clamp(device.Z * _sign.Z, -max, max));
    }
}
