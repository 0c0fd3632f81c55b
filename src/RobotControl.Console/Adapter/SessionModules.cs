using System.Collections.Concurrent;
using RobotControl.Robot.Bus;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// What the live session keeps of the modules besides what the robot core holds: how many the last discovery found,
/// and the friendly names given on the bus page in this session.
/// <para>
/// Written when the session opens and then by the bus's owner (a discovery, a rename: commands between cycles); read
/// by the status thread.
/// </para>
/// </summary>
internal sealed class SessionModules(SessionEvents events)
{
    private readonly ConcurrentDictionary<int, string> _names = [];
    private volatile int _found;

    /// <summary>Modules the last discovery found.</summary>
    public int Found => _found;

    /// <summary>Keeps what a discovery found and logs it; returns its lines.</summary>
    public List<string> Record(DiscoveryReport report)
    {
        _found = report.Present.Count;
        var lines = report.Lines().Select(l => l.Trim()).ToList();
        foreach (var line in lines)
        {
            events.Add("discovery", line);
        }

        return lines;
    }

    /// <summary>Gives module <paramref name="id"/> a friendly name.</summary>
    public void Rename(int id, string name) => _names[id] = name;

    /// <summary>The module's friendly name, or its name in the robot file.</summary>
    public string NameOf(RobotController module) => _names.TryGetValue(module.Id, out var name) ? name : module.Name;
}
