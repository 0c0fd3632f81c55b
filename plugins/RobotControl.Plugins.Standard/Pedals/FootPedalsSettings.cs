using RobotControl.Definitions.Json;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Standard.Pedals;

/// <summary>Where a pedal instance reads from.</summary>
public enum PedalSourceKind
{
    /// <summary>A simulated box following <see cref="FootPedalsSettings.Script"/>.</summary>
    Scripted,

    /// <summary>A pedal box on <see cref="FootPedalsSettings.Transport"/>.</summary>
    Serial,
}

/// <summary>Settings of <see cref="FootPedalsPlugin"/>.</summary>
public sealed record FootPedalsSettings : PluginSettings
{
    /// <summary>Source of pedal states.</summary>
    [Setting("Source: scripted (simulated box) or serial (a pedal box on a transport).")]
    public PedalSourceKind Source { get; init; } = PedalSourceKind.Scripted;

    /// <summary>Transport of the serial box.</summary>
    [Setting("Transport of the pedal box, e.g. serial:/dev/ttyUSB1?baud=9600 (serial source).")]
    public string Transport { get; init; } = "";

    /// <summary>Script of the simulated box.</summary>
    [Setting("Script of the simulated box: time_s:mask steps, e.g. 2.5:1,3.1:0 (bit i = pedal i+1).")]
    public string Script { get; init; } = "";

    /// <summary>Number of pedals.</summary>
    [Setting("Number of pedals (outputs pedal1..pedalN).", Minimum = 1, Maximum = 8)]
    public int Pedals { get; init; } = 2;

    /// <inheritdoc />
    public override IEnumerable<JsonProblem> CheckConsistency()
    {
        if (Source == PedalSourceKind.Serial && string.IsNullOrWhiteSpace(Transport))
        {
            yield return new JsonProblem("transport", "a serial pedal box needs a transport");
        }
    }
}
