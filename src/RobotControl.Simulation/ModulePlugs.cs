using System.Collections.Concurrent;
using RobotControl.Definitions.Model;

namespace RobotControl.Simulation;

/// <summary>
/// Which of a <see cref="VirtualRobot"/>'s modules are plugged in (all of them, unless they came from the factory),
/// each named by its ID in the robot file, and the changes other threads post for the thread that runs the simulation.
/// </summary>
internal sealed class ModulePlugs(ModuleDefinition[] modules, VirtualRobotOptions options)
{
    private readonly bool[] _connected = modules.Select((_, i) => !options.Factory || i < options.ConnectedAtStart).ToArray();
    private readonly ConcurrentQueue<Action<VirtualRobot>> _posted = new();

    /// <summary>True when the module at <paramref name="index"/> (robot file order) is plugged in.</summary>
    public bool IsConnected(int index) => _connected[index];

    /// <summary>Records that the module at <paramref name="index"/> is plugged in or not.</summary>
    public void Set(int index, bool connected) => _connected[index] = connected;

    /// <summary>The index of the next module still in the box (robot file order), or -1 when all are in.</summary>
    public int NextInBox => Array.IndexOf(_connected, false);

    /// <summary>The index of the module the robot file numbers <paramref name="id"/>.</summary>
    /// <exception cref="KeyNotFoundException">The robot file has no such module.</exception>
    public int IndexOf(byte id)
    {
        for (var i = 0; i < modules.Length; i++)
        {
            if (modules[i].Id == id)
            {
                return i;
            }
        }

        throw new KeyNotFoundException($"the robot has no module with ID {id}");
    }

    /// <summary>The index of module <paramref name="moduleId"/>, which must be plugged in to <paramref name="action"/> it.</summary>
    /// <exception cref="InvalidOperationException">It is not plugged in.</exception>
    public int ConnectedIndex(byte moduleId, string action)
    {
        var index = IndexOf(moduleId);
        return _connected[index]
            ? index
            : throw new InvalidOperationException($"cannot {action} module {moduleId} ({modules[index].Name}): it is not plugged in (connect it first)");
    }

    /// <summary>Queues <paramref name="change"/> for the simulation's thread (thread-safe).</summary>
    public void Post(Action<VirtualRobot> change) => _posted.Enqueue(change);

    /// <summary>Applies every queued change to <paramref name="robot"/>, on the simulation's thread.</summary>
    public void RunPosted(VirtualRobot robot)
    {
        while (_posted.TryDequeue(out var change))
        {
            change(robot);
        }
    }
}
