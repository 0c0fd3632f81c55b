using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Standard.Pedals;

/// <summary>
/// Foot pedals: outputs <c>pedal1..pedalN</c> (1 = pressed) from a serial pedal box (read on its own thread) or a
/// scripted simulated box. Wire a pedal to a clutch or a haptic lock. A box that disconnects reads as released.
/// </summary>
[PluginType("foot_pedals", Description = "Foot pedals from a serial pedal box or a scripted simulated box.")]
public sealed class FootPedalsPlugin : Plugin<FootPedalsSettings>
{
    private readonly OutputPort[] _pedals;

    /// <summary>Creates the plug-in with the source its settings name.</summary>
    public FootPedalsPlugin(FootPedalsSettings settings, PluginContext context)
        : this(settings, context, CreateSource(settings, context))
    {
    }

    /// <summary>Creates the plug-in on a given source.</summary>
    public FootPedalsPlugin(FootPedalsSettings settings, PluginContext context, IPedalSource source)
        : base(settings, context)
    {
        ArgumentNullException.ThrowIfNull(source);
        Source = source;
        _pedals = [.. Enumerable.Range(1, Settings.Pedals).Select(i => DeclareOutput($"pedal{i}", SafeValue.Zero, "", $"pedal {i} (1 = pressed)"))];
    }

    /// <summary>The source.</summary>
    public IPedalSource Source { get; }

    /// <inheritdoc />
    public override void Start(in TickContext context) => Source.Start();

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        var mask = Source.Read(context.TimeSeconds);
        for (var i = 0; i < _pedals.Length; i++)
        {
            Write(_pedals[i], (mask >> i) & 1);
        }
    }

    /// <inheritdoc />
    public override void Stop() => Source.Dispose();

    private static IPedalSource CreateSource(FootPedalsSettings settings, PluginContext context)
    {
        ArgumentNullException.ThrowIfNull(settings);
        ArgumentNullException.ThrowIfNull(context);
        SettingsSchema.For(typeof(FootPedalsSettings)).ThrowIfInvalid(settings, context.InstanceName);
        return settings.Source == PedalSourceKind.Serial
            ? new SerialPedalSource(() => context.OpenDevice(settings.Transport))
            : new ScriptedPedalSource(settings.Script);
    }
}
