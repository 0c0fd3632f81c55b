using RobotControl.Definitions.Json;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Observation;

namespace RobotControl.Runtime.Graph;

/// <summary>
/// A graph under construction: plug-in instances by name, the global input registry (every instance's inputs as
/// <c>instance.input</c>, removed with the instance) and wires from outputs to any number of inputs (each input has
/// at most one source). <see cref="Compile"/> checks it and fixes the execution order once. Not thread-safe.
/// </summary>
public sealed class PluginGraph
{
    private readonly List<Plugin> _instances = [];
    private readonly Dictionary<string, Plugin> _byName = new(StringComparer.Ordinal);
    private readonly Dictionary<string, (Plugin Instance, int Index)> _inputRegistry = new(StringComparer.Ordinal);
    private readonly List<Wire> _wires = [];

    /// <summary>Instances in the order they were added.</summary>
    public IReadOnlyList<Plugin> Instances => _instances;

    /// <summary>Wires in the order they were added.</summary>
    public IReadOnlyList<Wire> Wires => _wires;

    /// <summary>The global input registry: every registered input signal name.</summary>
    public IReadOnlyCollection<string> RegisteredInputs => _inputRegistry.Keys;

    /// <summary>The instance named <paramref name="name"/>, or null.</summary>
    public Plugin? Find(string name) => _byName.GetValueOrDefault(name);

    /// <summary>Adds an instance and registers its inputs.</summary>
    /// <exception cref="GraphException">The name is taken or malformed.</exception>
    public void Add(Plugin instance)
    {
        ArgumentNullException.ThrowIfNull(instance);
        var problem = CheckName(instance.Name);
        if (problem is not null)
        {
            throw new GraphException(problem);
        }

        _instances.Add(instance);
        _byName.Add(instance.Name, instance);
        foreach (var input in instance.Inputs)
        {
            _inputRegistry.Add(SignalName.Join(instance.Name, input.Name), (instance, input.Index));
        }
    }

    /// <summary>Why <paramref name="name"/> cannot name a new instance, or null when it can.</summary>
    public string? CheckName(string name)
    {
        if (string.IsNullOrWhiteSpace(name) || name.Contains('.', StringComparison.Ordinal) || name.Any(char.IsWhiteSpace))
        {
            return $"instance name '{name}' must be non-empty without dots or spaces";
        }

        return _byName.ContainsKey(name) ? $"duplicate instance name '{name}'" : null;
    }

    /// <summary>Removes an instance, its inputs from the registry and every wire touching it.</summary>
    public bool Remove(string name)
    {
        if (!_byName.Remove(name, out var instance))
        {
            return false;
        }

        _instances.Remove(instance);
        foreach (var input in instance.Inputs)
        {
            _inputRegistry.Remove(SignalName.Join(name, input.Name));
        }

        _wires.RemoveAll(w => InstanceOf(w.From) == name || InstanceOf(w.To) == name);
        return true;
    }

    /// <summary>Connects an output to an input.</summary>
    /// <exception cref="GraphException">Unknown signal, an input given as source, or an input that already has a source.</exception>
    public void Connect(string from, string to, bool delayed = false)
    {
        var problem = TryConnect(new Wire(from, to, delayed));
        if (problem is not null)
        {
            throw new GraphException(problem);
        }
    }

    /// <summary>Connects a wire; returns why it cannot be connected (nothing changes then), or null.</summary>
    public string? TryConnect(Wire wire)
    {
        ArgumentNullException.ThrowIfNull(wire);
        var fromProblem = CheckOutput(wire.From);
        if (fromProblem is not null)
        {
            return fromProblem;
        }

        if (!_inputRegistry.ContainsKey(wire.To))
        {
            return FindOutput(wire.To) is not null
                ? $"'{wire.To}' is an output; a wire must end at an input"
                : $"unknown input '{wire.To}'{Suggest(wire.To, _inputRegistry.Keys)}";
        }

        var existing = _wires.FirstOrDefault(w => w.To == wire.To);
        if (existing is not null)
        {
            return $"input '{wire.To}' is already wired from '{existing.From}'{(existing.Origin.Length > 0 ? $" ({existing.Origin})" : "")}; an input has one source";
        }

        _wires.Add(wire);
        return null;
    }

    /// <summary>Checks the graph and fixes its execution order.</summary>
    /// <exception cref="GraphException">A cycle without a delayed wire, or an observer whose outputs feed others.</exception>
    public GraphProgram Compile()
    {
        var problems = new List<JsonProblem>();
        var order = Order(problems);
        if (problems.Count > 0)
        {
            throw new GraphException(problems);
        }

        return new GraphProgram(order, _wires, _byName);
    }

    /// <summary>
    /// What <see cref="Compile"/> would reject (a cycle without a delayed wire, naming its instances; an observer whose
    /// outputs feed others), without compiling: a graph file's check lists these beside the problems it found reading
    /// the file, on the instances and wires that could be created.
    /// </summary>
    public IReadOnlyList<JsonProblem> Check()
    {
        var problems = new List<JsonProblem>();
        Order(problems);
        return problems;
    }

    private List<Plugin> Order(List<JsonProblem> problems)
    {
        var index = new Dictionary<Plugin, int>();
        for (var i = 0; i < _instances.Count; i++)
        {
            index[_instances[i]] = i;
        }

        foreach (var wire in _wires)
        {
            var source = _byName[InstanceOf(wire.From)];
            var target = _byName[InstanceOf(wire.To)];
            if (source is ISignalObserver && target is not ISignalObserver)
            {
                problems.Add(new JsonProblem(wire.Origin, $"'{source.Name}' observes every signal and runs last, so its output '{wire.From}' cannot feed '{wire.To}'"));
            }
        }

        return TopologicalOrder(index, problems);
    }

    private static string InstanceOf(string signal) => SignalName.TrySplit(signal, out var instance, out _) ? instance : "";

    private static string Suggest(string wanted, IEnumerable<string> known)
    {
        var prefix = InstanceOf(wanted) + ".";
        var candidates = known.Where(k => k.StartsWith(prefix, StringComparison.Ordinal)).Order(StringComparer.Ordinal).Take(12).ToList();
        return candidates.Count > 0 ? $" (that instance has: {string.Join(", ", candidates)})" : "";
    }

    private string? CheckOutput(string signal)
    {
        if (!SignalName.TrySplit(signal, out var instance, out _))
        {
            return $"'{signal}' is not an instance.port signal name";
        }

        if (!_byName.ContainsKey(instance))
        {
            return $"unknown instance '{instance}' in '{signal}'";
        }

        if (FindOutput(signal) is not null)
        {
            return null;
        }

        return _inputRegistry.ContainsKey(signal)
            ? $"'{signal}' is an input; a wire must start at an output"
            : $"unknown output '{signal}'{Suggest(signal, AllOutputs())}";
    }

    private (Plugin Instance, int Index)? FindOutput(string signal)
    {
        if (!SignalName.TrySplit(signal, out var name, out var port) || !_byName.TryGetValue(name, out var instance))
        {
            return null;
        }

        var i = instance.IndexOfOutput(port);
        return i < 0 ? null : (instance, i);
    }

    private IEnumerable<string> AllOutputs() =>
        _instances.SelectMany(p => p.Outputs.Select(o => SignalName.Join(p.Name, o.Name)));

    private List<Plugin> TopologicalOrder(Dictionary<Plugin, int> index, List<JsonProblem> problems)
    {
        // Kahn's algorithm over undelayed wires. Ties keep insertion order, so the order is stable and predictable;
        // observers are taken only when no other instance is ready, so they run after everything they watch.
        var n = _instances.Count;
        var indegree = new int[n];
        var successors = new List<int>[n];
        var predecessors = new List<(int Source, Wire Wire)>[n];
        for (var i = 0; i < n; i++)
        {
            successors[i] = [];
            predecessors[i] = [];
        }

        foreach (var wire in _wires.Where(w => !w.Delayed))
        {
            var s = index[_byName[InstanceOf(wire.From)]];
            var t = index[_byName[InstanceOf(wire.To)]];
            successors[s].Add(t);
            predecessors[t].Add((s, wire));
            indegree[t]++;
        }

        var order = new List<Plugin>(n);
        var done = new bool[n];
        var taken = 0;
        while (taken < n)
        {
            var next = -1;
            for (var i = 0; i < n; i++)
            {
                if (!done[i] && indegree[i] == 0 && (next < 0 || (_instances[next] is ISignalObserver && _instances[i] is not ISignalObserver)))
                {
                    next = i;
                    if (_instances[i] is not ISignalObserver)
                    {
                        break;
                    }
                }
            }

            if (next < 0)
            {
                // Every cycle is named: the one found is taken out as if it ran, and the search goes on.
                foreach (var member in ReportCycle(predecessors, done, problems))
                {
                    Take(member);
                }

                continue;
            }

            Take(next);
            order.Add(_instances[next]);
        }

        return order;

        void Take(int node)
        {
            done[node] = true;
            taken++;
            foreach (var target in successors[node])
            {
                indegree[target]--;
            }
        }
    }

    /// <summary>Names one cycle among the instances not yet done; returns its instances.</summary>
    private List<int> ReportCycle(List<(int Source, Wire Wire)>[] predecessors, bool[] done, List<JsonProblem> problems)
    {
        // Every instance left over has an undelayed source that is also left over, so walking backwards from any of
        // them never ends: the first repeated instance closes a cycle.
        var current = Array.IndexOf(done, false);
        var walk = new List<(int Node, Wire Via)>();
        var seenAt = new Dictionary<int, int>();
        while (!seenAt.ContainsKey(current))
        {
            seenAt[current] = walk.Count;
            var (source, wire) = predecessors[current].First(p => !done[p.Source]);
            walk.Add((current, wire));
            current = source;
        }

        // walk[k] = (node, wire into node from walk[k+1].Node); the cycle is walk[seenAt[current]..], reversed.
        var cycle = walk.Skip(seenAt[current]).Reverse().ToList();
        var names = cycle.Select(c => _instances[c.Node].Name).Prepend(_instances[current].Name);
        var wires = cycle.Select(c => c.Via).ToList();
        problems.Add(new JsonProblem(
            wires[0].Origin,
            $"cycle without a delayed wire: {string.Join(" -> ", names)} (wires: {string.Join(", ", wires.Select(w => $"{w.From} -> {w.To}"))}); mark one wire of the cycle \"delayed\": true to feed it back one tick later"));
        return [.. cycle.Select(c => c.Node)];
    }
}
