using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Standard.Conditioning;

/// <summary>
/// Scaling: p_out = reference + ratio (p_in - reference), for fine motion. The ratio is the input <c>ratio</c>, which
/// starts at the <c>ratio</c> setting: a graph may wire it, or (unwired) the console sets it while the arm's clutch is
/// held, so the clutch absorbs the change and the tool tip does not jump. It is read once per tick; a value outside the
/// setting's range (or not finite) is ignored and the last good ratio kept.
/// </summary>
[PluginType("scaling", Description = "Scales displacement from a reference point by a ratio.")]
public sealed class ScalingPlugin : Plugin<ScalingSettings>
{
    /// <summary>The input that carries the ratio.</summary>
    public const string RatioInput = "ratio";

    private static readonly SettingDescriptor RatioSetting = SettingsSchema.For(typeof(ScalingSettings)).Find(RatioInput)!;
    private readonly InputPort[] _in;
    private readonly OutputPort[] _out;
    private readonly InputPort _ratioIn;
    private readonly OutputPort _ratioOut;
    private readonly double[] _reference;
    private double _ratio;

    /// <summary>Creates the plug-in.</summary>
    public ScalingPlugin(ScalingSettings settings, PluginContext context)
        : base(settings, context)
    {
        _reference = [Settings.ReferenceXMm, Settings.ReferenceYMm, Settings.ReferenceZMm];
        _ratio = Settings.Ratio;
        string[] axes = ["x", "y", "z"];
        _in = [.. axes.Select((a, i) => DeclareInput(a, "mm", $"position {a}", _reference[i]))];
        _ratioIn = DeclareInput(RatioInput, "", $"motion ratio ({RatioSetting.Minimum}..{RatioSetting.Maximum}; starts at the ratio setting)", Settings.Ratio);
        _out = [.. axes.Select((a, i) => DeclareOutput(a, SafeValue.HoldLastFinite, "mm", $"scaled position {a}", _reference[i]))];
        _ratioOut = DeclareOutput(RatioInput, SafeValue.HoldLastFinite, "", "the motion ratio in effect (for the haptic walls, which undo it)", Settings.Ratio);
    }

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        var requested = Read(_ratioIn);
        if (RatioSetting.Accepts(requested))
        {
            _ratio = requested;
        }

        for (var i = 0; i < 3; i++)
        {
            Write(_out[i], _reference[i] + (_ratio * (Read(_in[i]) - _reference[i])));
        }

        Write(_ratioOut, _ratio);
    }
}
