using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;

namespace RobotControl.Plugins.Standard.Conditioning;

/// <summary>
/// Clutch: while engaged the target holds still and the device may move freely; on release, motion resumes relative
/// to the new device position (the difference is accumulated into an offset), so the target never jumps at press or
/// release. Applies to position and orientation angles alike.
/// <para>
/// The input <c>follow</c> (wire the robot's <c>teleop_enabled</c>) clutches the same way while it is 0: when the
/// robot stops following (a soft trip, pedal up) the target goes back to where it was one tick before the robot said
/// so (the tick that said so may already carry a stalled host's or a jumped master's sample), and holds; when the
/// robot follows again the motion resumes from there, relative to the device's new position. So re-engaging after a
/// stall or a jump starts where the arm holds, not where the hand went meanwhile. Unwired, it is 1.
/// </para>
/// </summary>
[PluginType("clutch", Description = "Holds the target while the clutch is held; resumes without a jump on release.")]
public sealed class ClutchPlugin : Plugin<ClutchSettings>
{
    private static readonly string[] Channels = ["x", "y", "z", "roll", "pitch", "yaw"];
    private readonly InputPort[] _in;
    private readonly OutputPort[] _out;
    private readonly InputPort _clutch;
    private readonly InputPort _follow;
    private readonly OutputPort _engagedOut;
    private readonly double[] _offset = new double[Channels.Length];
    private readonly double[] _outBefore = new double[Channels.Length]; // the outputs as the previous tick found them
    private bool _engaged;
    private bool _following = true;
    private bool _first = true;

    /// <summary>Creates the plug-in.</summary>
    public ClutchPlugin(ClutchSettings settings, PluginContext context)
        : base(settings, context)
    {
        _in = [.. Channels.Select((c, i) => DeclareInput(c, i < 3 ? "mm" : "rad", $"target {c}"))];
        _clutch = DeclareInput("clutch", "", "clutch button or pedal");
        _follow = DeclareInput("follow", "", "1 while the robot follows (wire robot.teleop_enabled); 0 holds the target as the clutch does", 1);
        _out = [.. Channels.Select((c, i) => DeclareOutput(c, SafeValue.HoldLastFinite, i < 3 ? "mm" : "rad", $"clutched target {c}"))];
        _engagedOut = DeclareOutput("engaged", SafeValue.HoldLastFinite, "", "1 while the target is held: the clutch is held or the robot is not following");
    }

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        var value = Read(_clutch);
        var following = _first || Read(_follow) >= 0.5; // the first tick reads the robot's output from before its first tick
        var engaged = !following || (Settings.Inverted ? value < Settings.Threshold : value >= Settings.Threshold);
        if (_first)
        {
            // Start as if released at the current position (zero offset), whatever the button says.
            _first = false;
            for (var i = 0; i < _in.Length; i++)
            {
                Write(_out[i], Read(_in[i]));
                _outBefore[i] = Read(_in[i]);
            }
        }

        if (_following && !following)
        {
            // The robot stopped following: back to the target from before the tick that told us.
            for (var i = 0; i < _in.Length; i++)
            {
                Write(_out[i], _outBefore[i]);
            }
        }

        for (var i = 0; i < _in.Length; i++)
        {
            _outBefore[i] = ReadOutput(_out[i]);
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
        _following = following;
        Write(_engagedOut, engaged ? 1 : 0);
    }
}
