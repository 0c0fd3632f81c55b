using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;

namespace RobotControl.Plugins.Standard.Haptics;

/// <summary>
/// Haptic lock: while locked, a stiff spring holds the handle at the point where the lock engaged and the pose
/// passed on toward the robot is paused. On unlock the pose resumes relative to where the handle is then (like a
/// clutch), so the robot target never jumps. Sits between the device and homing for the pose, and adds its spring
/// force to the force going back to the device.
/// </summary>
[PluginType("haptic_lock", Description = "Holds the handle with a stiff spring and pauses pose output while locked.")]
public sealed class HapticLockPlugin : Plugin<HapticLockSettings>
{
    private static readonly string[] Channels = ["x", "y", "z", "roll", "pitch", "yaw"];
    private static readonly string[] Axes = ["x", "y", "z"];
    private readonly InputPort[] _pose;
    private readonly InputPort _lock;
    private readonly InputPort[] _forceIn;
    private readonly OutputPort[] _poseOut;
    private readonly OutputPort[] _forceOut;
    private readonly OutputPort _locked;
    private readonly double[] _lockPoint = new double[3];
    private readonly double[] _offset = new double[Channels.Length];
    private bool _wasLocked;

    /// <summary>Creates the plug-in.</summary>
    public HapticLockPlugin(HapticLockSettings settings, PluginContext context)
        : base(settings, context)
    {
        _pose = [.. Channels.Select((c, i) => DeclareInput(c, i < 3 ? "mm" : "rad", $"handle {c} (device frame)"))];
        _lock = DeclareInput("lock", "", "lock button or pedal");
        _forceIn = [.. Axes.Select(a => DeclareInput($"f{a}_in", "N", $"force to add to, device {a}"))];
        _poseOut = [.. Channels.Select((c, i) => DeclareOutput(c, SafeValue.HoldLastFinite, i < 3 ? "mm" : "rad", $"{c} passed on (paused while locked)"))];
        _forceOut = [.. Axes.Select(a => DeclareOutput($"f{a}", SafeValue.Zero, "N", $"force with the lock spring, device {a}"))];
        _locked = DeclareOutput("locked", SafeValue.HoldLastFinite, "", "1 while locked");
    }

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        var locked = Read(_lock) >= Settings.Threshold;
        if (locked && !_wasLocked)
        {
            for (var k = 0; k < 3; k++)
            {
                _lockPoint[k] = Read(_pose[k]);
            }
        }
        else if (!locked && _wasLocked)
        {
            for (var i = 0; i < _pose.Length; i++)
            {
                _offset[i] = ReadOutput(_poseOut[i]) - Read(_pose[i]);
            }
        }

        if (!locked)
        {
            for (var i = 0; i < _pose.Length; i++)
            {
                Write(_poseOut[i], Read(_pose[i]) + _offset[i]);
            }
        }

        var max = Settings.MaxForceN;
        for (var k = 0; k < 3; k++)
        {
            var spring = locked ? Math.Clamp(Settings.StiffnessNPerMm * (_lockPoint[k] - Read(_pose[k])), -max, max) : 0.0;
            Write(_forceOut[k], Read(_forceIn[k]) + spring);
        }

        _wasLocked = locked;
        Write(_locked, locked ? 1 : 0);
    }
}
