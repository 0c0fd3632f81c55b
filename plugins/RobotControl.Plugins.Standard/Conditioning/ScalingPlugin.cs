using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;

namespace RobotControl.Plugins.Standard.Conditioning;

/// <summary>Scaling: p_out = reference + ratio (p_in - reference), for fine motion.</summary>
[PluginType("scaling", Description = "Scales displacement from a reference point by a ratio.")]
public sealed class ScalingPlugin : Plugin<ScalingSettings>
{
    private readonly InputPort[] _in;
    private readonly OutputPort[] _out;
    private readonly double[] _reference;

    /// <summary>Creates the plug-in.</summary>
    public ScalingPlugin(ScalingSettings settings, PluginContext context)
        : base(settings, context)
    {
        _reference = [Settings.ReferenceXMm, Settings.ReferenceYMm, Settings.ReferenceZMm];
        string[] axes = ["x", "y", "z"];
        _in = [.. axes.Select((a, i) => DeclareInput(a, "mm", $"position {a}", _reference[i]))];
        _out = [.. axes.Select((a, i) => DeclareOutput(a, SafeValue.HoldLastFinite, "mm", $"scaled position {a}", _reference[i]))];
    }

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        var ratio = Settings.Ratio;
        for (var i = 0; i < 3; i++)
        {
            Write(_out[i], _reference[i] + (ratio * (Read(_in[i]) - _reference[i])));
        }
    }
}
