using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Settings;
using RobotControl.Plugins.Touch.Backends;
using RobotControl.Plugins.Touch.Simulation;

namespace RobotControl.Plugins.Touch;

/// <summary>
/// A Geomagic Touch: outputs stylus position (mm), orientation (rad) and two buttons (0/1) in the device frame;
/// inputs a 3-DOF force (N, device frame) to render, normally fed back one tick later from the haptics chain.
/// The device itself is behind <see cref="ITouchBackend"/>.
/// </summary>
[PluginType("touch", Description = "Geomagic Touch haptic device (simulated back end: scripted hand with a hand model).")]
public sealed class TouchPlugin : Plugin<TouchSettings>
{
    private readonly InputPort _fx;
    private readonly InputPort _fy;
    private readonly InputPort _fz;
    private readonly OutputPort _x;
    private readonly OutputPort _y;
    private readonly OutputPort _z;
    private readonly OutputPort _roll;
    private readonly OutputPort _pitch;
    private readonly OutputPort _yaw;
    private readonly OutputPort _button1;
    private readonly OutputPort _button2;

    /// <summary>Creates the plug-in with the back end its settings name.</summary>
    public TouchPlugin(TouchSettings settings, PluginContext context)
        : this(settings, context, CreateBackend(settings, context))
    {
    }

    /// <summary>Creates the plug-in on a given back end.</summary>
    public TouchPlugin(TouchSettings settings, PluginContext context, ITouchBackend backend)
        : base(settings, context)
    {
        ArgumentNullException.ThrowIfNull(backend);
        Backend = backend;
        _fx = DeclareInput("force_x", "N", "force to render along device x");
        _fy = DeclareInput("force_y", "N", "force to render along device y");
        _fz = DeclareInput("force_z", "N", "force to render along device z");
        _x = DeclareOutput("x", SafeValue.HoldLastFinite, "mm", "stylus x (device frame)");
        _y = DeclareOutput("y", SafeValue.HoldLastFinite, "mm", "stylus y (device frame)");
        _z = DeclareOutput("z", SafeValue.HoldLastFinite, "mm", "stylus z (device frame)");
        _roll = DeclareOutput("roll", SafeValue.HoldLastFinite, "rad", "gimbal roll");
        _pitch = DeclareOutput("pitch", SafeValue.HoldLastFinite, "rad", "gimbal pitch");
        _yaw = DeclareOutput("yaw", SafeValue.HoldLastFinite, "rad", "gimbal yaw");
        _button1 = DeclareOutput("button1", SafeValue.Zero, "", "first button (1 = pressed)");
        _button2 = DeclareOutput("button2", SafeValue.Zero, "", "second button (1 = pressed)");
    }

    /// <summary>The back end.</summary>
    public ITouchBackend Backend { get; }

    /// <inheritdoc />
    public override void Start(in TickContext context) => Backend.Open();

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        var sample = Backend.Exchange(context.TimeSeconds, new TouchForce(Read(_fx), Read(_fy), Read(_fz)));
        Write(_x, sample.XMm);
        Write(_y, sample.YMm);
        Write(_z, sample.ZMm);
        Write(_roll, sample.RollRad);
        Write(_pitch, sample.PitchRad);
        Write(_yaw, sample.YawRad);
        Write(_button1, sample.Button1 ? 1 : 0);
        Write(_button2, sample.Button2 ? 1 : 0);
    }

    /// <inheritdoc />
    public override void Stop() => Backend.Dispose();

    private static SimulatedTouchBackend CreateBackend(TouchSettings settings, PluginContext context)
    {
        ArgumentNullException.ThrowIfNull(settings);
        ArgumentNullException.ThrowIfNull(context);
        SettingsSchema.For(typeof(TouchSettings)).ThrowIfInvalid(settings, context.InstanceName);
        var script = HandScript.Load(context.ResolvePath(settings.Script), settings.RecordingPrefix);
        var hand = new HandModel(settings.HandMassKg, settings.HandStiffnessNPerMm, settings.HandDampingNsPerMm);
        return new SimulatedTouchBackend(script, hand, settings.MaxForceN, settings.TimeOffsetS, settings.Repeat);
    }
}
