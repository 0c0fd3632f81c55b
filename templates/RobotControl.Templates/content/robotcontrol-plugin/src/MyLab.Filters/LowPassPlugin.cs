using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;

namespace MyLab.Filters;

/// <summary>
/// A first-order low-pass filter, e.g. against hand tremor between scaling and clutch:
/// y += (x - y) * dt / (tau + dt) with tau = 1 / (2 pi cutoff). The first tick passes the input through, so the
/// output does not sweep up from zero.
/// </summary>
[PluginType("mylab_filters_low_pass", Description = "First-order low-pass filter of one signal.")]
public sealed class LowPassPlugin : Plugin<LowPassSettings>
{
    private readonly InputPort _in;
    private readonly OutputPort _out;
    private readonly double _tau;
    private bool _primed;

    /// <summary>Declares the ports; the host (or the test harness) calls this with validated settings.</summary>
    public LowPassPlugin(LowPassSettings settings, PluginContext context)
        : base(settings, context)
    {
        _in = DeclareInput("in", "mm", "signal to filter");
        _out = DeclareOutput("out", SafeValue.HoldLastFinite, "mm", "filtered signal");
        _tau = 1 / (2 * Math.PI * Settings.CutoffHz);
    }

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        var x = Read(_in);
        if (!_primed)
        {
            _primed = true;
            Write(_out, x);
            return;
        }

        var y = ReadOutput(_out);
        var dt = context.PeriodSeconds;
        Write(_out, y + ((x - y) * dt / (_tau + dt)));
    }
}
