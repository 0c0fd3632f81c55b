using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Standard.Recording;

/// <summary>Settings of <see cref="RecorderPlugin"/>.</summary>
public sealed record RecorderSettings : PluginSettings
{
    /// <summary>The CSV file to write.</summary>
    [Setting("CSV file to write (relative to the graph file); overwritten at start.", IsFilePath = true, Required = true)]
    public string Path { get; init; } = "recording.csv";

    /// <summary>Record every this many ticks.</summary>
    [Setting("Record every this many ticks (1: every tick).", Minimum = 1, Maximum = 100000)]
    public int EveryTicks { get; init; } = 1;

    /// <summary>Rows buffered between the loop and the writer thread.</summary>
    [Setting("Rows buffered between the loop and the file writer; rows are dropped (and counted) when the disk falls this far behind.", Minimum = 16, Maximum = 10000000)]
    public int BufferRows { get; init; } = 20000;
}
