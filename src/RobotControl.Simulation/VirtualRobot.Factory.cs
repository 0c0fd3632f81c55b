using RobotControl.Bus.Protocol;
using RobotControl.Simulation.Native;

namespace RobotControl.Simulation;

/// <summary>
/// A box of boards (<see cref="VirtualRobotOptions.Factory"/>): modules fresh from the factory, all at the default ID,
/// plugged in one at a time. A module is named by its ID in the robot file (which board it is, whatever ID it answers
/// at now); unplugged, it neither hears nor answers and keeps only its FRAM.
/// </summary>
public sealed partial class VirtualRobot
{
    /// <summary>The ID a module fresh from the factory answers at (the control table's default <c>id</c>).</summary>
    public static byte FactoryId => (byte)ControlTable.Firmware["id"].Default;

    /// <summary>True when the modules came from the factory (<see cref="VirtualRobotOptions.Factory"/>).</summary>
    public bool IsFactory => _options.Factory;

    /// <summary>True when the module the robot file numbers <paramref name="moduleId"/> is plugged in.</summary>
    /// <exception cref="KeyNotFoundException">The robot file has no such module.</exception>
    public bool IsConnected(byte moduleId) => _plugs.IsConnected(_plugs.IndexOf(moduleId));

    /// <summary>Plugs in the next module still in the box (robot file order); returns its robot-file ID, or null when all are in.</summary>
    public byte? ConnectNext()
    {
        var next = _plugs.NextInBox;
        if (next < 0)
        {
            return null;
        }

        Connect(_modules[next].Id);
        return _modules[next].Id;
    }

    /// <summary>Plugs module <paramref name="moduleId"/> in: it powers on from its FRAM (nothing happens when it already is).</summary>
    /// <exception cref="KeyNotFoundException">The robot file has no such module.</exception>
    public void Connect(byte moduleId)
    {
        var index = _plugs.IndexOf(moduleId);
        if (!_plugs.IsConnected(index))
        {
            _axes.Feed(_bus);
            FirmwareHost.Check(FirmwareHost.PowerCycle(_bus, index), "rcfw_power_cycle");
            _plugs.Set(index, connected: true);
        }
    }

    /// <summary>Unplugs module <paramref name="moduleId"/>: its power goes, its FRAM stays.</summary>
    /// <exception cref="KeyNotFoundException">The robot file has no such module.</exception>
    public void Disconnect(byte moduleId)
    {
        var index = _plugs.IndexOf(moduleId);
        FirmwareHost.Check(FirmwareHost.PowerOff(_bus, index), "rcfw_power_off");
        _plugs.Set(index, connected: false);
    }

    /// <summary>
    /// Cuts module <paramref name="moduleId"/>'s power once <paramref name="bytes"/> more bytes are written into its FRAM:
    /// the record being written is torn there (a power cut mid-way through a parameter write). <see cref="PowerCycle"/>
    /// powers it again, from what its FRAM kept.
    /// </summary>
    public void CutPowerAfterFramBytes(byte moduleId, int bytes) => FirmwareHost.Check(FirmwareHost.FramCutAfter(_bus, _plugs.ConnectedIndex(moduleId, "cut the power of"), bytes), "rcfw_fram_cut_after");

    /// <summary>The ID module <paramref name="moduleId"/> (the robot file's) answers at now, read from its table (not over the bus).</summary>
    /// <exception cref="InvalidOperationException">The module is not plugged in.</exception>
    public byte BusId(byte moduleId)
    {
        _ = _plugs.ConnectedIndex(moduleId, "read the ID of");
        Span<byte> id = stackalloc byte[1];
        PeekTable(moduleId, (ushort)ControlTable.Firmware["id"].At(0), id);
        return id[0];
    }

    /// <summary>
    /// Hands <paramref name="change"/> to the thread that runs the simulation (thread-safe): <see cref="Serve"/> applies
    /// it between two turns. The way another thread (a console's stdin) plugs modules in or power-cycles them.
    /// </summary>
    public void Post(Action<VirtualRobot> change)
    {
        ArgumentNullException.ThrowIfNull(change);
        _plugs.Post(change);
    }

    private void RunPosted() => _plugs.RunPosted(this);
}
