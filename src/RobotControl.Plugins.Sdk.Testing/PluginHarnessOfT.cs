namespace RobotControl.Plugins.Sdk.Testing;

/// <summary>
/// Runs one plug-in without the host: create it with <see cref="PluginHarness.Create{TPlugin}"/>, <see cref="Set"/> inputs by name,
/// <see cref="Tick"/>, read outputs with the indexer. The first tick calls <see cref="Plugin.Start"/>; disposing calls
/// <see cref="Plugin.Stop"/> (and <see cref="IDisposable.Dispose"/> of a disposable plug-in). Exceptions from the
/// plug-in reach the test unchanged.
/// </summary>
/// <typeparam name="TPlugin">The plug-in type.</typeparam>
public sealed class PluginHarness<TPlugin> : IDisposable
    where TPlugin : Plugin
{
    private bool _started;
    private bool _stopped;

    internal PluginHarness(TPlugin plugin, ManualClock clock, TimeSpan period)
    {
        Plugin = plugin;
        Clock = clock;
        Period = period;
    }

    /// <summary>The plug-in under test.</summary>
    public TPlugin Plugin { get; }

    /// <summary>The plug-in's clock (<see cref="PluginContext.Time"/>), one <see cref="Period"/> further per tick.</summary>
    public ManualClock Clock { get; }

    /// <summary>The loop period.</summary>
    public TimeSpan Period { get; }

    /// <summary>Ticks run so far.</summary>
    public long TickCount { get; private set; }

    /// <summary>The current value of the output named <paramref name="output"/>.</summary>
    /// <exception cref="ArgumentException">No such output.</exception>
    public double this[string output] => Plugin.GetOutput(output);

    /// <summary>Sets the input named <paramref name="input"/> (it keeps the value until set again).</summary>
    /// <exception cref="ArgumentException">No such input.</exception>
    public PluginHarness<TPlugin> Set(string input, double value)
    {
        Plugin.SetInput(input, value);
        return this;
    }

    /// <summary>Marks the inputs named <paramref name="inputs"/> as driven by wires, as a graph does (the plug-in's <c>IsWired</c>).</summary>
    /// <exception cref="ArgumentException">No such input.</exception>
    public PluginHarness<TPlugin> Wire(params string[] inputs)
    {
        ArgumentNullException.ThrowIfNull(inputs);
        Plugin.MarkWired(inputs.Select(name => Plugin.IndexOfInput(name) is var index and >= 0 ? index : throw new ArgumentException($"'{Plugin.Name}' has no input '{name}'", nameof(inputs))));
        return this;
    }

    /// <summary>Runs <paramref name="count"/> ticks (the first one ever starts the plug-in).</summary>
    /// <exception cref="ObjectDisposedException">The harness was disposed.</exception>
    public PluginHarness<TPlugin> Tick(int count = 1)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(count);
        ObjectDisposedException.ThrowIf(_stopped, this);
        for (var i = 0; i < count; i++)
        {
            var context = new TickContext(TickCount, Clock.GetTimestamp(), Period * TickCount, Period);
            if (!_started)
            {
                _started = true;
                Plugin.Start(context);
            }

            Plugin.Tick(context);
            TickCount++;
            Clock.Advance(Period);
        }

        return this;
    }

    /// <summary>Ticks for <paramref name="duration"/> of loop time (rounded to whole periods).</summary>
    public PluginHarness<TPlugin> Run(TimeSpan duration) => Tick((int)Math.Round(duration / Period));

    /// <summary>Stops the plug-in (if it was started) and disposes it if it is disposable.</summary>
    public void Dispose()
    {
        if (_stopped)
        {
            return;
        }

        _stopped = true;
        if (_started)
        {
            Plugin.Stop();
        }

        (Plugin as IDisposable)?.Dispose();
    }
}
