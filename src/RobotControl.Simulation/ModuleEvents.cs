using RobotControl.Simulation.Native;

namespace RobotControl.Simulation;

/// <summary>Module events a <see cref="VirtualRobot"/> has scheduled at simulated times (resets with their cause, transmit lines breaking), fired in time order.</summary>
internal sealed class ModuleEvents
{
    private readonly List<ModuleEvent> _events = [];

    /// <summary>When the next event is due, µs of simulated time; <see cref="long.MaxValue"/> when none is.</summary>
    public long NextUs => _events.Count > 0 ? _events[0].AtUs : long.MaxValue;

    /// <summary>Resets module <paramref name="module"/> (its index) with <paramref name="cause"/> at <paramref name="atUs"/>.</summary>
    public void Reset(long atUs, int module, byte cause) => Add(new ModuleEvent(atUs, module, cause, BreaksLine: false));

    /// <summary>Breaks module <paramref name="module"/>'s transmit line at <paramref name="atUs"/>.</summary>
    public void BreakLine(long atUs, int module) => Add(new ModuleEvent(atUs, module, 0, BreaksLine: true));

    /// <summary>Fires on <paramref name="bus"/> every event due at <paramref name="nowUs"/>.</summary>
    public void FireDue(nint bus, long nowUs)
    {
        while (_events.Count > 0 && _events[0].AtUs <= nowUs)
        {
            var e = _events[0];
            FirmwareHost.Check(
                e.BreaksLine ? FirmwareHost.SetTransmitBroken(bus, e.Module, 1) : FirmwareHost.Reset(bus, e.Module, e.Cause),
                e.BreaksLine ? "rcfw_set_tx_broken" : "rcfw_reset");
            _events.RemoveAt(0);
        }
    }

    private void Add(ModuleEvent e)
    {
        _events.Add(e);
        _events.Sort((a, b) => a.AtUs.CompareTo(b.AtUs));
    }

    /// <summary>A module event at a simulated time: a reset with its cause, or its transmit line breaking.</summary>
    private readonly record struct ModuleEvent(long AtUs, int Module, byte Cause, bool BreaksLine);
}
