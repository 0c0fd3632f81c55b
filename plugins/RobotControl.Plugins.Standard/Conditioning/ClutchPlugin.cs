using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;

namespace RobotControl.Plugins.Standard.Conditioning;

/// <summary>
/// Clutch: while engaged the target holds still and the device may move freely; on release, motion resumes relative
/// to the new device position (the difference is accumulated into an offset), so the target never jumps at press or
/// release. Applies to position and orientation angles alike.
/// </summary>
[PluginType("clutch", Description = "Holds the target while the clutch is held; resumes without a jump on release.")]
public sealed class ClutchPlugin : Plugin<ClutchSettings>
{
    private static readonly string[] Channels = ["x", "y", "z", "roll", "pitch", "yaw"];
    private readonly InputPort[] _in;
    private readonly OutputPort[] _out;
    private readonly InputPort _clutch;
    private readonly OutputPort _engagedOut;
    private readonly double[] _offset = new double[Channels.Length];
    private bool _engaged;
    private bool _first = true;

    /// <summary>Creates the plug-in.</summary>
    public ClutchPlugin(ClutchSettings settings, PluginContext context)
        : base(settings, context)
    {
        _in = [.. Channels.Select((c, i) => DeclareInput(c, i < 3 ? "mm" : "rad", $"target {c}"))];
        _clutch = DeclareInput("clutch", "", "clutch button or pedal");
        _out = [.. Channels.Select((c, i) => DeclareOutput(c, SafeValue.HoldLastFinite, i < 3 ? "mm" : "rad", $"clutched target {c}"))];
        _engagedOut = DeclareOutput("engaged", SafeValue.HoldLastFinite, "", "1 while the clutch is held");
    }

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        var value = Read(_clutch);
        var engaged = Settings.Inverted ? value < Settings.Threshold : value >= Settings.Threshold;
        if (_first)
        {
            // Start as if released at the current position (zero offset), whatever the button says.
            _first = false;
            for (var i = 0; i < _in.Length; i++)
            {
                Write(_out[i], Read(_in[i]));
            }
        }

        if (engaged)
        {
            // Held: outputs keep their last values.
        }
        else if (_engaged)
        {
            // Released: continue from where the target stopped.
            for (var i = 0; i < _in.Length; i++)
            {
                _offset[i] = ReadOutput(_out[i]) - Read(_in[i]);
            }
        }

        if (!engaged)
        {
            for (var i = 0; i < _in.Length; i++)
            {
                Write(_out[i], Read(_in[i]) + _offset[i]);
            }
        }

        _engaged = engaged;
        Write(_engagedOut, engaged ? 1 : 0);
    }
}
