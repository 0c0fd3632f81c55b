using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Faults;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Settings;
using RobotControl.Plugins.Touch.Backends;

namespace RobotControl.Plugins.Touch;

/// <summary>
/// A Geomagic Touch: outputs stylus position (mm), orientation (rad) and two buttons (0/1) in the device frame;
/// inputs a 3-DOF force (N, device frame) to render, normally fed back one tick later from the haptics chain, and
/// <c>force_enable</c>, the seam for the safety supervisor's run level (below 0.5: no force reaches the device).
/// <c>sample_age_ms</c> says how old the reading is (the master timeout: wire it to the robot's <c>arm.input_age_ms</c>);
/// <c>speed_mm_s</c> how fast the tip moved between the last two readings, for every back end alike: beyond the
/// robot file's <c>safety.master_speed_max_mm_s</c> (a jump no hand can make) the pose and buttons keep the last
/// plausible reading, so nothing downstream (homing, scaling, the clutch, the IK's warm start) ever sees it; wire it
/// to the robot's <c>arm.input_speed_mm_s</c> and the supervisor trips <c>master_jump</c>.
/// The device itself is behind <see cref="ITouchBackend"/>, chosen by the <c>backend</c> setting. Injected device
/// faults (<see cref="IFaultInjectable"/>) go to the back end when it takes them (the simulated one does, the real device does not).
/// </summary>
[PluginType("touch", Description = "Geomagic Touch haptic device (back ends: simulated scripted hand, or the real device through OpenHaptics).")]
public sealed class TouchPlugin : Plugin<TouchSettings>, IFaultInjectable
{
    private readonly InputPort _fx;
    private readonly InputPort _fy;
    private readonly InputPort _fz;
    private readonly InputPort _forceEnable;
    private readonly OutputPort _x;
    private readonly OutputPort _y;
    private readonly OutputPort _z;
    private readonly OutputPort _roll;
    private readonly OutputPort _pitch;
    private readonly OutputPort _yaw;
    private readonly OutputPort _button1;
    private readonly OutputPort _button2;
    private readonly OutputPort _sampleAge;
    private readonly OutputPort _speed;
    private readonly TipSpeed _motion = new();
    private readonly double _speedLimit;

    /// <summary>Creates the plug-in with the back end its settings name.</summary>
    public TouchPlugin(TouchSettings settings, PluginContext context)
        : this(settings, context, TouchBackends.Create)
    {
    }

    /// <summary>Creates the plug-in on a given back end.</summary>
    public TouchPlugin(TouchSettings settings, PluginContext context, ITouchBackend backend)
        : this(settings, context, Given(backend))
    {
    }

    // The settings are validated once, by the base constructor, before the back end is made from them.
    private TouchPlugin(TouchSettings settings, PluginContext context, Func<TouchSettings, PluginContext, ITouchBackend> backend)
        : base(settings, context)
    {
        Backend = backend(Settings, Context);
        _speedLimit = (Context.Robot?.Safety ?? new Definitions.Model.SafetyLimits()).MasterSpeedMaxMmPerS;
        _fx = DeclareInput("force_x", "N", "force to render along device x");
        _fy = DeclareInput("force_y", "N", "force to render along device y");
        _fz = DeclareInput("force_z", "N", "force to render along device z");
        _forceEnable = DeclareInput("force_enable", "", "1 = force may reach the device, 0 = zero force (the safety supervisor's run level)", 1);
        _x = DeclareOutput("x", SafeValue.HoldLastFinite, "mm", "stylus x (device frame)");
        _y = DeclareOutput("y", SafeValue.HoldLastFinite, "mm", "stylus y (device frame)");
        _z = DeclareOutput("z", SafeValue.HoldLastFinite, "mm", "stylus z (device frame)");
        _roll = DeclareOutput("roll", SafeValue.HoldLastFinite, "rad", "gimbal roll");
        _pitch = DeclareOutput("pitch", SafeValue.HoldLastFinite, "rad", "gimbal pitch");
        _yaw = DeclareOutput("yaw", SafeValue.HoldLastFinite, "rad", "gimbal yaw");
        _button1 = DeclareOutput("button1", SafeValue.Zero, "", "first button (1 = pressed)");
        _button2 = DeclareOutput("button2", SafeValue.Zero, "", "second button (1 = pressed)");
        _sampleAge = DeclareOutput("sample_age_ms", SafeValue.HoldLastFinite, "ms", "how old the reading is (0: new this tick); wire it to the robot's arm.input_age_ms (the master timeout)");
        _speed = DeclareOutput("speed_mm_s", SafeValue.HoldLastFinite, "mm/s", "stylus tip speed implied by the last two readings, before any scaling; wire it to the robot's arm.input_speed_mm_s (a jump no hand can make is a soft trip)");
    }

    /// <summary>The back end.</summary>
    public ITouchBackend Backend { get; }

    /// <inheritdoc />
    public override void Start(in TickContext context) => Backend.Open();

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        var sample = Backend.Exchange(context.TimeSeconds, new TouchForce(Read(_fx), Read(_fy), Read(_fz), Read(_forceEnable) >= 0.5));
        var speed = _motion.Speed(context.TimeSeconds - (sample.AgeMs * 1e-3), sample.XMm, sample.YMm, sample.ZMm);
        Write(_speed, speed);
        Write(_sampleAge, sample.AgeMs);
        if (!(speed <= _speedLimit))
        {
            return; // a jump no hand can make: nothing downstream sees it, the pose keeps the last plausible reading
        }

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

    /// <inheritdoc />
    public bool CanTake(DeviceFaultKind kind) => Backend is IFaultInjectable faults && faults.CanTake(kind);

    /// <inheritdoc />
    public void Inject(DeviceFault fault)
    {
        ArgumentNullException.ThrowIfNull(fault);
        if (Backend is not IFaultInjectable faults)
        {
            throw new ArgumentException($"Touch '{Name}' ({Backend.Description}) cannot take a {fault} fault", nameof(fault));
        }

        faults.Inject(fault);
    }

    private static Func<TouchSettings, PluginContext, ITouchBackend> Given(ITouchBackend backend)
    {
        ArgumentNullException.ThrowIfNull(backend);
        return (_, _) => backend;
    }
}
