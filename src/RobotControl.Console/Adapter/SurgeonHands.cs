using RobotControl.Definitions.Model;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Settings;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.GraphFiles;
using RobotControl.Runtime.Robot;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// The hands of the surgeon's view, found in the running graph by plug-in type (never by instance name): an arm's hand
/// is the set of instances upstream of the robot node's inputs of that arm (following undelayed wires), its clutch,
/// haptic lock, scaling and inverse kinematics are the instances of those types in it, and its haptic walls the
/// <c>haptic_walls</c> instance fed by that inverse kinematics. Pedals are the outputs of <c>foot_pedals</c> instances.
/// Built once; the ratio is read from the scaling plug-in's input when asked.
/// </summary>
internal sealed class SurgeonHands
{
    // Plug-in type names (the [PluginType] names of the standard plug-ins).
    private const string ClutchType = "clutch";
    private const string LockType = "haptic_lock";
    private const string ScalingType = "scaling";
    private const string IkType = "inverse_kinematics";
    private const string WallsType = "haptic_walls";
    private const string PedalsType = "foot_pedals";
    private const string RatioInput = "ratio";

    private readonly List<Hand> _hands = [];

    public SurgeonHands(GraphDocument document, GraphProgram program, RobotDefinition robot)
    {
        var types = document.Instances.ToDictionary(i => i.Name, i => i.Type);
        var plugins = program.Order.ToDictionary(p => p.Name);
        foreach (var arm in robot.Arms)
        {
            var upstream = Upstream(document.Wires, w => w.To.StartsWith($"{RobotNode.InstanceName}.{arm.Name}.", StringComparison.Ordinal));
            string? Of(string type) => upstream.FirstOrDefault(n => types.GetValueOrDefault(n) == type);
            var ik = Of(IkType);
            var walls = ik is null ? null : types.Where(t => t.Value == WallsType).Select(t => t.Key)
                .FirstOrDefault(w => Upstream(document.Wires, x => x.To.StartsWith($"{w}.", StringComparison.Ordinal)).Contains(ik));
            if (ik is null && Of(ScalingType) is null && Of(ClutchType) is null)
            {
                continue; // an arm the graph does not drive from a hand
            }

            var scaling = Of(ScalingType) is { } s ? plugins.GetValueOrDefault(s) : null;
            var clutch = Of(ClutchType) is { } c ? plugins.GetValueOrDefault(c) : null;
            _hands.Add(new Hand(
                arm.Name,
                clutch,
                Of(LockType),
                scaling,
                scaling?.IndexOfInput(RatioInput) ?? -1,
                scaling is null ? null : Setting(scaling, RatioInput),
                scaling is not null && document.Wires.All(w => w.To != $"{scaling.Name}.{RatioInput}"),
                walls,
                walls is null ? 0 : Number(plugins[walls], "max_force_n"),
                ik));
        }

        Pedals = [.. document.Instances.Where(i => i.Type == PedalsType).SelectMany(i => plugins[i.Name].Outputs.Select(o => $"{i.Name}.{o.Name}"))
            .Select(signal => new PedalView(signal, Drives(document.Wires, signal)))];
    }

    public IReadOnlyList<PedalView> Pedals { get; }

    /// <summary>The hand of <paramref name="arm"/>, or null.</summary>
    public Hand? Of(string arm) => _hands.FirstOrDefault(h => h.Arm == arm);

    /// <summary>The hands as the page sees them, with the ratios in use now.</summary>
    public IReadOnlyList<HandView> Views() => [.. _hands.Select(h => new HandView(
        h.Arm,
        h.Clutch is null ? null : $"{h.Clutch.Name}.engaged",
        h.Lock is null ? null : $"{h.Lock}.locked",
        h.Scaling?.Name,
        h.Scale,
        h.ScaleMin,
        h.ScaleMax,
        h.ScaleSettable,
        h.Walls is null ? [] : [$"{h.Walls}.fx", $"{h.Walls}.fy", $"{h.Walls}.fz"],
        h.WallMaxForceN,
        h.Ik is null ? null : $"{h.Ik}.error_mm"))];

    /// <summary>Every instance upstream (through undelayed wires) of the wires <paramref name="into"/> selects, robot node excluded.</summary>
    private static HashSet<string> Upstream(IReadOnlyList<Wire> wires, Func<Wire, bool> into)
    {
        var found = new HashSet<string>(StringComparer.Ordinal);
        var queue = new Queue<string>(wires.Where(into).Select(w => InstanceOf(w.From)));
        while (queue.TryDequeue(out var name))
        {
            if (name == RobotNode.InstanceName || !found.Add(name))
            {
                continue;
            }

            foreach (var w in wires.Where(w => !w.Delayed && InstanceOf(w.To) == name))
            {
                queue.Enqueue(InstanceOf(w.From));
            }
        }

        return found;
    }

    private static string InstanceOf(string signal) => signal[..signal.IndexOf('.', StringComparison.Ordinal)];

    /// <summary>What a pedal output is wired to, in words.</summary>
    private string Drives(IReadOnlyList<Wire> wires, string signal)
    {
        var targets = wires.Where(w => w.From == signal).Select(w => w.To switch
        {
            "robot.pedal" => "run level (pedal)",
            "robot.estop" => "E-STOP",
            var to when _hands.FirstOrDefault(h => h.Clutch is not null && to == $"{h.Clutch.Name}.clutch") is { } h => $"{h.Arm} clutch",
            var to when _hands.FirstOrDefault(h => h.Lock is not null && to == $"{h.Lock}.lock") is { } h => $"{h.Arm} haptic lock",
            var to => to,
        }).ToList();
        return targets.Count == 0 ? "nothing" : string.Join(", ", targets);
    }

    private static double Number(Plugin plugin, string setting) =>
        Setting(plugin, setting) is { } d
            ? Convert.ToDouble(d.Property.GetValue(plugin.SettingsObject), System.Globalization.CultureInfo.InvariantCulture)
            : 0;

    private static SettingDescriptor? Setting(Plugin plugin, string name) =>
        plugin.SettingsObject is { } settings ? SettingsSchema.For(settings.GetType()).Find(name) : null;

    /// <summary>One hand.</summary>
    internal sealed record Hand(
        string Arm,
        Plugin? Clutch,
        string? Lock,
        Plugin? Scaling,
        int RatioIndex,
        SettingDescriptor? ScaleSetting,
        bool ScaleSettable,
        string? Walls,
        double WallMaxForceN,
        string? Ik)
    {
        /// <summary>Smallest ratio the scaling's input takes (its ratio setting's range; 0 without one).</summary>
        public double ScaleMin => ScaleSetting?.Minimum ?? 0;

        /// <summary>Largest ratio the scaling's input takes.</summary>
        public double ScaleMax => ScaleSetting?.Maximum ?? 0;

        /// <summary>The ratio in the scaling plug-in's input now.</summary>
        public double? Scale => Scaling is null || RatioIndex < 0 ? null : Scaling.GetInput(RatioIndex);

        /// <summary>True while the clutch is held (its <c>engaged</c> output).</summary>
        public bool Clutched => Clutch is not null && Clutch.GetOutput("engaged") >= 0.5;
    }
}
