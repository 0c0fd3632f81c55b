using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Sdk;

/// <summary>
/// The base of every plug-in: named double inputs and outputs declared in the constructor, then a
/// <see cref="Start"/> / <see cref="Tick(in TickContext)"/> / <see cref="Stop"/> lifecycle driven by the control loop.
/// <para>
/// Values live in arrays owned by the host (the graph lays every instance's inputs and outputs into two shared
/// buffers); <see cref="Read"/> and <see cref="Write"/> are plain indexed accesses, so a tick allocates nothing.
/// A plug-in that throws from <see cref="Tick(in TickContext)"/> is faulted by the host: it is not ticked again, its
/// outputs go to their <see cref="SafeValue"/>s, and sinks downstream of it (the robot) hold position.
/// </para>
/// </summary>
public abstract class Plugin
{
    private readonly List<PortInfo> _inputs = [];
    private readonly List<PortInfo> _outputs = [];
    private double[] _inputValues = [];
    private double[] _outputValues = [];
    private int _inputBase;
    private int _outputBase;
    private bool _bound;
    private bool[] _wired = [];

    /// <summary>Creates a plug-in; declare ports in the derived constructor.</summary>
    /// <param name="context">The host's context (instance name, robot, clock).</param>
    protected Plugin(PluginContext context)
    {
        ArgumentNullException.ThrowIfNull(context);
        Context = context;
    }

    /// <summary>The instance's name in the graph.</summary>
    public string Name => Context.InstanceName;

    /// <summary>The host's context.</summary>
    public PluginContext Context { get; }

    /// <summary>Declared inputs in declaration order.</summary>
    public IReadOnlyList<PortInfo> Inputs => _inputs;

    /// <summary>Declared outputs in declaration order.</summary>
    public IReadOnlyList<PortInfo> Outputs => _outputs;

    /// <summary>The instance's settings (null for a plug-in without settings).</summary>
    public virtual PluginSettings? SettingsObject => null;

    /// <summary>
    /// True during a tick when a plug-in that feeds this one (directly or further upstream) has faulted. Sinks that
    /// command hardware hold position instead of acting on the (safe but stale) values.
    /// </summary>
    protected internal bool UpstreamFaulted { get; internal set; }

    /// <summary>Called once before the first tick, on the loop thread.</summary>
    /// <param name="context">The first tick's context.</param>
    public virtual void Start(in TickContext context)
    {
    }

    /// <summary>Reads inputs, computes, writes outputs. Must not block or allocate.</summary>
    /// <param name="context">The tick.</param>
    public abstract void Tick(in TickContext context);

    /// <summary>Called once after the last tick (also for a faulted plug-in); release devices and files here.</summary>
    public virtual void Stop()
    {
    }

    /// <summary>Index of the input named <paramref name="name"/>, or -1.</summary>
    public int IndexOfInput(string name) => IndexOf(_inputs, name);

    /// <summary>Index of the output named <paramref name="name"/>, or -1.</summary>
    public int IndexOfOutput(string name) => IndexOf(_outputs, name);

    /// <summary>Current value of input <paramref name="index"/> (host, GUI and tests).</summary>
    public double GetInput(int index) => _inputValues[_inputBase + CheckIndex(index, _inputs.Count)];

    /// <summary>Sets input <paramref name="index"/> (host, GUI and tests; wired inputs are overwritten every tick).</summary>
    public void SetInput(int index, double value) => _inputValues[_inputBase + CheckIndex(index, _inputs.Count)] = value;

    /// <summary>Sets the input named <paramref name="name"/>.</summary>
    /// <exception cref="ArgumentException">No such input.</exception>
    public void SetInput(string name, double value)
    {
        var index = IndexOfInput(name);
        if (index < 0)
        {
            throw new ArgumentException($"'{Name}' has no input '{name}'", nameof(name));
        }

        SetInput(index, value);
    }

    /// <summary>Current value of output <paramref name="index"/>.</summary>
    public double GetOutput(int index) => _outputValues[_outputBase + CheckIndex(index, _outputs.Count)];

    /// <summary>Current value of the output named <paramref name="name"/>.</summary>
    /// <exception cref="ArgumentException">No such output.</exception>
    public double GetOutput(string name)
    {
        var index = IndexOfOutput(name);
        return index < 0 ? throw new ArgumentException($"'{Name}' has no output '{name}'", nameof(name)) : GetOutput(index);
    }

    /// <summary>Declares an input. Only in the constructor.</summary>
    /// <param name="name">Port name (unique among the inputs).</param>
    /// <param name="units">Units, e.g. <c>mm</c>.</param>
    /// <param name="description">What the value means.</param>
    /// <param name="initialValue">Value of the input until something writes it (and forever when unwired).</param>
    protected InputPort DeclareInput(string name, string units = "", string description = "", double initialValue = 0)
    {
        Declare(_inputs, name, units, description, initialValue, SafeValue.HoldLastFinite);
        _inputValues = Grow(_inputValues, initialValue);
        return new InputPort(_inputs.Count - 1);
    }

    /// <summary>Declares an output. Only in the constructor.</summary>
    /// <param name="name">Port name (unique among the outputs).</param>
    /// <param name="safeValue">What the output shows after a fault or a non-finite value.</param>
    /// <param name="units">Units, e.g. <c>N</c>.</param>
    /// <param name="description">What the value means.</param>
    /// <param name="initialValue">Value before the first tick.</param>
    protected OutputPort DeclareOutput(string name, SafeValue safeValue, string units = "", string description = "", double initialValue = 0)
    {
        Declare(_outputs, name, units, description, initialValue, safeValue);
        _outputValues = Grow(_outputValues, initialValue);
        return new OutputPort(_outputs.Count - 1);
    }

    /// <summary>Reads an input (allocation-free).</summary>
    protected double Read(InputPort port) => _inputValues[_inputBase + port.Index];

    /// <summary>Writes an output (allocation-free).</summary>
    protected void Write(OutputPort port, double value) => _outputValues[_outputBase + port.Index] = value;

    /// <summary>Reads back an output's current value.</summary>
    protected double ReadOutput(OutputPort port) => _outputValues[_outputBase + port.Index];

    /// <summary>
    /// True when a wire of the graph drives <paramref name="port"/>; an unwired input keeps its initial value. Known
    /// once the plug-in has joined a graph (from <see cref="Start"/> on); false before.
    /// </summary>
    protected bool IsWired(InputPort port) => port.Index < _wired.Length && _wired[port.Index];

    /// <summary>Records which inputs the graph's wires drive (called once when the graph is built).</summary>
    internal void MarkWired(IEnumerable<int> inputIndexes)
    {
        var wired = new bool[_inputs.Count];
        foreach (var index in inputIndexes)
        {
            wired[CheckIndex(index, _inputs.Count)] = true;
        }

        _wired = wired;
    }

    /// <summary>Moves the values into the host's shared buffers (called once when the graph is built).</summary>
    internal void Bind(double[] inputValues, int inputBase, double[] outputValues, int outputBase)
    {
        Array.Copy(_inputValues, _inputBase, inputValues, inputBase, _inputs.Count);
        Array.Copy(_outputValues, _outputBase, outputValues, outputBase, _outputs.Count);
        _inputValues = inputValues;
        _outputValues = outputValues;
        _inputBase = inputBase;
        _outputBase = outputBase;
        _bound = true;
    }

    private static int IndexOf(List<PortInfo> ports, string name)
    {
        for (var i = 0; i < ports.Count; i++)
        {
            if (string.Equals(ports[i].Name, name, StringComparison.Ordinal))
            {
                return i;
            }
        }

        return -1;
    }

    private static int CheckIndex(int index, int count)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(index);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(index, count);
        return index;
    }

    private static double[] Grow(double[] values, double initialValue)
    {
        var grown = new double[values.Length + 1];
        values.CopyTo(grown, 0);
        grown[^1] = initialValue;
        return grown;
    }

    private void Declare(List<PortInfo> ports, string name, string units, string description, double initialValue, SafeValue safeValue)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(name);
        ArgumentNullException.ThrowIfNull(units);
        ArgumentNullException.ThrowIfNull(description);
        if (_bound)
        {
            throw new InvalidOperationException($"'{Name}': ports are declared in the constructor, before the plug-in joins a graph");
        }

        if (IndexOf(ports, name) >= 0)
        {
            throw new ArgumentException($"'{Name}': port '{name}' is declared twice", nameof(name));
        }

        if (!double.IsFinite(initialValue))
        {
            throw new ArgumentOutOfRangeException(nameof(initialValue), $"'{Name}.{name}': the initial value must be finite");
        }

        ports.Add(new PortInfo(name, ports.Count, units, description, initialValue, safeValue));
    }
}
