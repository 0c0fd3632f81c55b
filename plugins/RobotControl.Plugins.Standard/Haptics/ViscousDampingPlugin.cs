using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;

namespace RobotControl.Plugins.Standard.Haptics;

/// <summary>
/// Viscous damping F = -b v on the handle (reduces tremor, damps a dropped handle). The velocity is the filtered
/// derivative of the handle position; the damping force is added to the force coming in (<c>fx_in</c>...), so it
/// chains after the walls.
/// </summary>
[PluginType("viscous_damping", Description = "Adds F = -b v from the handle's velocity to a force.")]
public sealed class ViscousDampingPlugin : Plugin<ViscousDampingSettings>
{
    private readonly InputPort[] _position;
    private readonly InputPort[] _forceIn;
    private readonly OutputPort[] _forceOut;
    private readonly double[] _last = new double[3];
    private readonly double[] _velocity = new double[3];
    private bool _primed;

    /// <summary>Creates the plug-in.</summary>
    public ViscousDampingPlugin(ViscousDampingSettings settings, PluginContext context)
        : base(settings, context)
    {
        string[] axes = ["x", "y", "z"];
        _position = [.. axes.Select(a => DeclareInput(a, "mm", $"handle {a} (device frame)"))];
        _forceIn = [.. axes.Select(a => DeclareInput($"f{a}_in", "N", $"force to add to, device {a}"))];
        _forceOut = [.. axes.Select(a => DeclareOutput($"f{a}", SafeValue.Zero, "N", $"force with damping, device {a}"))];
    }

    /// <summary>The filtered handle velocity, mm/s.</summary>
    public ReadOnlySpan<double> Velocity => _velocity;

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        var dt = context.PeriodSeconds;
        var alpha = 1.0 - Math.Exp(-2 * Math.PI * Settings.VelocityFilterHz * dt);
        var max = Settings.MaxForceN;
        for (var k = 0; k < 3; k++)
        {
            var p = Read(_position[k]);
            if (_primed)
            {
                _velocity[k] += alpha * (((p - _last[k]) / dt) - _velocity[k]);
            }

            _last[k] = p;
            var damping = Math.Clamp(-Settings.DampingNsPerMm * _velocity[k], -max, max);
            Write(_forceOut[k], Read(_forceIn[k]) + damping);
        }

        _primed = true;
    }
}
