using RobotControl.Plugins.Sdk;

namespace RobotControl.TestSupport;

/// <summary>Drives one plug-in by hand: set inputs by name, tick, read outputs by name.</summary>
public sealed class PluginDriver(Plugin plugin)
{
    private long _tick;

    public Plugin Plugin { get; } = plugin;

    public PluginDriver Start()
    {
        Plugin.Start(Ticks.At(0));
        return this;
    }

    public PluginDriver Set(params (string Name, double Value)[] inputs)
    {
        foreach (var (name, value) in inputs)
        {
            Plugin.SetInput(name, value);
        }

        return this;
    }

    public PluginDriver Tick(int count = 1)
    {
        for (var i = 0; i < count; i++)
        {
            Plugin.Tick(Ticks.At(_tick++));
        }

        return this;
    }

    public double this[string output] => Plugin.GetOutput(output);

    public (double X, double Y, double Z) Xyz(string prefix = "") => (this[prefix + "x"], this[prefix + "y"], this[prefix + "z"]);
}
