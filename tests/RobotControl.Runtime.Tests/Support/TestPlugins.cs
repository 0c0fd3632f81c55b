using RobotControl.Definitions.Json;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Runtime.Tests.Support;

/// <summary>Outputs the tick index (and a constant), recording the order in which it ran.</summary>
internal sealed class CounterSource : Plugin
{
    private readonly OutputPort _value;
    private readonly List<string>? _log;

    public CounterSource(string name, List<string>? log = null)
        : base(PluginContext.Standalone(name))
    {
        _log = log;
        _value = DeclareOutput("value", SafeValue.HoldLastFinite);
    }

    public override void Tick(in TickContext context)
    {
        _log?.Add(Name);
        Write(_value, context.Index);
    }
}

/// <summary>out = in * gain + bias; may throw or emit NaN on a chosen tick.</summary>
internal sealed class Gain : Plugin
{
    private readonly InputPort _in;
    private readonly InputPort _second;
    private readonly OutputPort _out;
    private readonly OutputPort _force;
    private readonly double _gain;
    private readonly List<string>? _log;

    public Gain(string name, double gain = 1.0, List<string>? log = null)
        : base(PluginContext.Standalone(name))
    {
        _gain = gain;
        _log = log;
        _in = DeclareInput("in");
        _second = DeclareInput("second");
        _out = DeclareOutput("out", SafeValue.HoldLastFinite);
        _force = DeclareOutput("force", SafeValue.Zero);
    }

    public long ThrowAtTick { get; init; } = -1;

    public long NaNAtTick { get; init; } = -1;

    public List<double> Seen { get; } = [];

    public override void Tick(in TickContext context)
    {
        _log?.Add(Name);
        if (context.Index == ThrowAtTick)
        {
            throw new InvalidOperationException("boom");
        }

        var x = Read(_in);
        Seen.Add(x);
        var y = context.Index == NaNAtTick ? double.NaN : (x * _gain) + Read(_second);
        Write(_out, y);
        Write(_force, y);
    }
}

internal sealed record ExampleSettings : PluginSettings
{
    [Setting("Ratio applied to displacements.", Minimum = 0.05, Maximum = 1.0)]
    public double Ratio { get; init; } = 0.5;

    [Setting("Reference x.", Units = "mm")]
    public double ReferenceXMm { get; init; }

    [Setting("Number of samples.", Minimum = 1, Maximum = 10)]
    public int Samples { get; init; } = 2;

    [Setting("Mode.")]
    public SafeValue Mode { get; init; } = SafeValue.Zero;

    [Setting("Script file.", IsFilePath = true, Required = true)]
    public string Script { get; init; } = "script.csv";

    public override IEnumerable<JsonProblem> CheckConsistency()
    {
        if (Samples > 5 && Ratio > 0.9)
        {
            yield return new JsonProblem("samples", "more than 5 samples need a ratio of at most 0.9");
        }
    }
}

[PluginType("example", Description = "A test plug-in with settings.")]
internal sealed class ExamplePlugin : Plugin<ExampleSettings>
{
    private readonly InputPort _in;
    private readonly OutputPort _out;

    public ExamplePlugin(ExampleSettings settings, PluginContext context)
        : base(settings, context)
    {
        _in = DeclareInput("in", "mm");
        _out = DeclareOutput("out", SafeValue.HoldLastFinite, "mm");
    }

    public override void Tick(in TickContext context) => Write(_out, Read(_in) * Settings.Ratio);
}
