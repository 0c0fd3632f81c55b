using System.Diagnostics;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Observation;
using RobotControl.Plugins.Sdk.Ports;

namespace RobotControl.Runtime.Graph;

/// <summary>
/// A compiled graph: instances in dependency order, every input and output laid out in two shared arrays, wires as
/// index pairs. <see cref="Tick"/> pushes values from sources through downstream instances, copies delayed wires at
/// the end (their inputs see the value one tick later), isolates faulted instances and replaces non-finite outputs
/// with their safe values. A tick allocates nothing. Ticks run on one thread; <see cref="Faults"/> may be read from
/// any thread.
/// </summary>
public sealed class GraphProgram
{
    private readonly Plugin[] _order;
    private readonly double[] _inputs;
    private readonly double[] _outputs;
    private readonly double[] _lastFinite;
    private readonly bool[] _safeIsFixed; // zero or initial: the output goes to _fixedSafe; else it holds its last finite value
    private readonly double[] _fixedSafe;
    private readonly int[] _outputStart; // per instance (order index), CSR into outputs; length n + 1
    private readonly int[] _wireStart; // per instance, CSR into the undelayed wires feeding it; length n + 1
    private readonly int[] _wireSource; // output slot
    private readonly int[] _wireTarget; // input slot
    private readonly int[] _wireSourceNode; // order index of the source instance
    private readonly int[] _delayedSource;
    private readonly int[] _delayedTarget;
    private readonly int[] _delayedSourceNode;
    private readonly int[] _delayedTargetNode;
    private readonly bool[] _faulted;
    private readonly bool[] _tainted;
    private readonly long[] _nonFinite;
    private readonly Lock _faultGate = new();
    private readonly List<PluginFault> _faults = [];
    private int _faultCount;
    private bool _started;

    internal GraphProgram(IReadOnlyList<Plugin> order, IReadOnlyList<Wire> wires, IReadOnlyDictionary<string, Plugin> byName)
    {
        var n = order.Count;
        _order = [.. order];
        var position = new Dictionary<Plugin, int>();
        var inputStart = new int[n + 1];
        _outputStart = new int[n + 1];
        for (var i = 0; i < n; i++)
        {
            position[_order[i]] = i;
            inputStart[i + 1] = inputStart[i] + _order[i].Inputs.Count;
            _outputStart[i + 1] = _outputStart[i] + _order[i].Outputs.Count;
        }

        _inputs = new double[inputStart[n]];
        _outputs = new double[_outputStart[n]];
        _lastFinite = new double[_outputs.Length];
        _safeIsFixed = new bool[_outputs.Length];
        _fixedSafe = new double[_outputs.Length];
        var outputNames = new string[_outputs.Length];
        var inputNames = new string[_inputs.Length];
        for (var i = 0; i < n; i++)
        {
            var p = _order[i];
            p.Bind(_inputs, inputStart[i], _outputs, _outputStart[i]);
            foreach (var o in p.Outputs)
            {
                var slot = _outputStart[i] + o.Index;
                _safeIsFixed[slot] = o.SafeValue is SafeValue.Zero or SafeValue.Initial;
                _fixedSafe[slot] = o.SafeValue == SafeValue.Initial ? o.InitialValue : 0.0;
                _lastFinite[slot] = o.InitialValue;
                outputNames[slot] = SignalName.Join(p.Name, o.Name);
            }

            foreach (var input in p.Inputs)
            {
                inputNames[inputStart[i] + input.Index] = SignalName.Join(p.Name, input.Name);
            }
        }

        (int Source, int Target, int SourceNode, int TargetNode) Resolve(Wire w)
        {
            SignalName.TrySplit(w.From, out var fromName, out var fromPort);
            SignalName.TrySplit(w.To, out var toName, out var toPort);
            var s = position[byName[fromName]];
            var t = position[byName[toName]];
            return (_outputStart[s] + _order[s].IndexOfOutput(fromPort), inputStart[t] + _order[t].IndexOfInput(toPort), s, t);
        }

        var resolved = wires.Select(w => (w.Delayed, Slots: Resolve(w))).ToArray();
        var wiredInputs = resolved.ToLookup(r => r.Slots.TargetNode, r => r.Slots.Target - inputStart[r.Slots.TargetNode]);
        for (var i = 0; i < n; i++)
        {
            _order[i].MarkWired(wiredInputs[i]);
        }

        var direct = resolved.Where(r => !r.Delayed).Select(r => r.Slots).OrderBy(r => r.TargetNode).ToArray();
        _wireStart = new int[n + 1];
        foreach (var r in direct)
        {
            _wireStart[r.TargetNode + 1]++;
        }

        for (var i = 0; i < n; i++)
        {
            _wireStart[i + 1] += _wireStart[i];
        }

        _wireSource = [.. direct.Select(r => r.Source)];
        _wireTarget = [.. direct.Select(r => r.Target)];
        _wireSourceNode = [.. direct.Select(r => r.SourceNode)];
        var delayed = resolved.Where(r => r.Delayed).Select(r => r.Slots).ToArray();
        _delayedSource = [.. delayed.Select(r => r.Source)];
        _delayedTarget = [.. delayed.Select(r => r.Target)];
        _delayedSourceNode = [.. delayed.Select(r => r.SourceNode)];
        _delayedTargetNode = [.. delayed.Select(r => r.TargetNode)];
        _faulted = new bool[n];
        _tainted = new bool[n];
        _nonFinite = new long[n];
        Wires = wires;
        Order = _order;
        Profile = new TickProfile(_order);
        OutputSignals = new SignalView(outputNames, _outputs);
        InputSignals = new SignalView(inputNames, _inputs);
        foreach (var observer in _order.OfType<ISignalObserver>())
        {
            observer.Attach(OutputSignals);
        }
    }

    /// <summary>Instances in execution order.</summary>
    public IReadOnlyList<Plugin> Order { get; }

    /// <summary>Where the ticks' time goes: the instance in its tick now, the slowest of the last tick (any thread).</summary>
    public TickProfile Profile { get; }

    /// <summary>The wires.</summary>
    public IReadOnlyList<Wire> Wires { get; }

    /// <summary>Every output signal (<c>instance.port</c>) and its current value.</summary>
    public SignalView OutputSignals { get; }

    /// <summary>Every input signal and its current value.</summary>
    public SignalView InputSignals { get; }

    /// <summary>Number of faults so far (cheap; read from any thread).</summary>
    public int FaultCount => Volatile.Read(ref _faultCount);

    /// <summary>A snapshot of the faults so far.</summary>
    public IReadOnlyList<PluginFault> Faults
    {
        get
        {
            lock (_faultGate)
            {
                return [.. _faults];
            }
        }
    }

    /// <summary>True when the instance has faulted.</summary>
    public bool IsFaulted(string instance) => _faulted[IndexOf(instance)];

    /// <summary>How many non-finite values the instance wrote (each replaced by the output's safe value).</summary>
    public long NonFiniteOutputs(string instance) => Volatile.Read(ref _nonFinite[IndexOf(instance)]);

    /// <summary>Starts every instance in order. An instance that throws is faulted (and not ticked).</summary>
    public void Start(in TickContext context)
    {
        if (_started)
        {
            throw new InvalidOperationException("the graph is already started");
        }

        _started = true;
        for (var i = 0; i < _order.Length; i++)
        {
            try
            {
                _order[i].Start(context);
            }
#pragma warning disable CA1031 // a plug-in's failure must not stop the others: it is isolated and reported
            catch (Exception ex)
#pragma warning restore CA1031
            {
                Fault(i, context, "start failed", ex);
            }
        }

        CopyDelayed(); // the first tick's delayed inputs carry what the sources showed after their Start
    }

    /// <summary>Runs one tick (allocation-free unless a plug-in faults).</summary>
    public void Tick(in TickContext context)
    {
        var order = _order;
        var inputs = _inputs;
        var outputs = _outputs;
        var profile = Profile;
        var slowest = -1;
        var slowestCost = -1L;
        for (var i = 0; i < order.Length; i++)
        {
            var tainted = _faulted[i];
            for (var w = _wireStart[i]; w < _wireStart[i + 1]; w++)
            {
                inputs[_wireTarget[w]] = outputs[_wireSource[w]];
                tainted |= _tainted[_wireSourceNode[w]];
            }

            for (var d = 0; d < _delayedTargetNode.Length; d++)
            {
                if (_delayedTargetNode[d] == i)
                {
                    tainted |= _tainted[_delayedSourceNode[d]];
                }
            }

            _tainted[i] = tainted;
            if (_faulted[i])
            {
                continue;
            }

            var plugin = order[i];
            plugin.UpstreamFaulted = tainted;
            var begin = Stopwatch.GetTimestamp();
            profile.Enter(i, begin);
            try
            {
                plugin.Tick(context);
            }
#pragma warning disable CA1031 // isolation: any exception faults this instance only
            catch (Exception ex)
#pragma warning restore CA1031
            {
                profile.Leave();
                Fault(i, context, "tick failed", ex);
                continue;
            }

            var cost = Stopwatch.GetTimestamp() - begin;
            profile.Leave();
            if (cost > slowestCost)
            {
                (slowest, slowestCost) = (i, cost);
            }

            Sanitise(i);
        }

        CopyDelayed();
        if (slowest >= 0)
        {
            profile.Complete(slowest, slowestCost);
        }
    }

    /// <summary>Delayed wires: each target takes its source's value, read by the next tick.</summary>
    private void CopyDelayed()
    {
        var inputs = _inputs;
        var outputs = _outputs;
        for (var d = 0; d < _delayedSource.Length; d++)
        {
            inputs[_delayedTarget[d]] = outputs[_delayedSource[d]];
        }
    }

    /// <summary>Stops every instance (in reverse order), faulted ones included; exceptions are recorded, not thrown.</summary>
    public void Stop()
    {
        if (!_started)
        {
            return;
        }

        _started = false;
        for (var i = _order.Length - 1; i >= 0; i--)
        {
            try
            {
                _order[i].Stop();
            }
#pragma warning disable CA1031 // stopping continues for the others
            catch (Exception ex)
#pragma warning restore CA1031
            {
                Record(new PluginFault(_order[i].Name, -1, TimeSpan.Zero, $"stop failed: {ex.GetType().Name}: {ex.Message}", ex));
            }
        }
    }

    private void Sanitise(int node)
    {
        var outputs = _outputs;
        for (var o = _outputStart[node]; o < _outputStart[node + 1]; o++)
        {
            var v = outputs[o];
            if (double.IsFinite(v))
            {
                _lastFinite[o] = v;
            }
            else
            {
                outputs[o] = _safeIsFixed[o] ? _fixedSafe[o] : _lastFinite[o];
                _nonFinite[node]++;
            }
        }
    }

    private void Fault(int node, in TickContext context, string what, Exception ex)
    {
        _faulted[node] = true;
        _tainted[node] = true;
        for (var o = _outputStart[node]; o < _outputStart[node + 1]; o++)
        {
            _outputs[o] = _safeIsFixed[o] ? _fixedSafe[o] : _lastFinite[o];
        }

        Record(new PluginFault(_order[node].Name, context.Index, context.Elapsed, $"{what}: {ex.GetType().Name}: {ex.Message}", ex));
    }

    private void Record(PluginFault fault)
    {
        lock (_faultGate)
        {
            _faults.Add(fault);
            _faultCount = _faults.Count;
        }
    }

    private int IndexOf(string instance)
    {
        for (var i = 0; i < _order.Length; i++)
        {
            if (_order[i].Name == instance)
            {
                return i;
            }
        }

        throw new ArgumentException($"no instance '{instance}'", nameof(instance));
    }
}
