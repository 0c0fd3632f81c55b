using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Transports;
using RobotControl.Definitions.Model;
using RobotControl.Modules;
using RobotControl.Simulation.Bus;
using RobotControl.Simulation.Models;
using RobotControl.Simulation.Native;
using RobotControl.Simulation.Time;
using RobotControl.Simulation.Units;

namespace RobotControl.Simulation;

/// <summary>
/// A robot's module bus with nothing real attached: every module runs the real firmware (the host build,
/// librcfw_host.so), fed by models of its motors (electrical and mechanical, from the datasheets), gearheads (ratio,
/// efficiency, backlash), Hall sensors, current sense (seeded noise) and non-linear joint pots. Bytes take wire time
/// at the bus baud. Time is simulated on a <see cref="ManualTimeProvider"/>: it moves when the host waits for bytes
/// (<see cref="OpenLink"/>), when told (<see cref="Advance"/>), or with the wall clock (<see cref="Serve"/>).
/// Faults: wire bit errors and lost bytes (<see cref="WireFaults"/>), module resets at a given time
/// (<see cref="ScheduleReset"/>), power cycles, stalled motors (<see cref="VirtualAxis.ObstacleTorqueNm"/>).
/// From the factory (<see cref="VirtualRobotOptions.Factory"/>): blank modules at the default ID, plugged in one at a
/// time. A unit's own pot curves: <see cref="VirtualRobotOptions.UnitVariationSeed"/>, <see cref="VirtualAxis.TruePot"/>.
/// A module is named by its ID in the robot file, whatever ID it answers at.
/// Not thread-safe: one thread drives it (the links it hands out run on the caller's thread; <see cref="Post"/> hands
/// it work from another).
/// </summary>
public sealed unsafe partial class VirtualRobot : IDisposable
{
    private readonly ManualTimeProvider _clock;
    private readonly long _clockOrigin;
    private readonly VirtualAxes _axes;
    private readonly ModulePlugs _plugs;
    private readonly ModuleDefinition[] _modules;
    private readonly WireFaultInjector _wire;
    private readonly long _physicsStepUs;
    private double _byteUs;
    private readonly ModuleEvents _moduleEvents = new();
    private readonly byte[] _scratch = new byte[4096];
    private const long MaxRealTimeLagUs = 20_000;
    private readonly VirtualRobotOptions _options;
    private nint _bus;
    private long _nowUs;
    private long _physicsUs;
    private long _hostFreeUs;

    /// <summary>Builds the virtual robot of <paramref name="robot"/> (its <c>modules</c> section) on <paramref name="clock"/>.</summary>
    /// <exception cref="ArgumentException">The robot file has no modules.</exception>
    public VirtualRobot(RobotDefinition robot, ManualTimeProvider clock, VirtualRobotOptions? options = null)
    {
        ArgumentNullException.ThrowIfNull(robot);
        ArgumentNullException.ThrowIfNull(clock);
        _options = options ?? new VirtualRobotOptions();
        if (robot.Modules.Modules.Count == 0)
        {
            throw new ArgumentException($"{robot.SourceFile}: the robot file has no modules section, so there is no bus to simulate", nameof(robot));
        }

        Definition = robot;
        _clock = clock;
        _clockOrigin = clock.GetTimestamp();
        _modules = robot.Modules.Modules.ToArray();
        _options.CheckFactory(_modules.Length);
        BaudRate = _options.Factory ? FactoryBaud : _options.BaudRate ?? robot.Modules.BaudRate;
        _physicsStepUs = Math.Max(1, (long)_options.PhysicsStep.TotalMicroseconds);
        _wire = new WireFaultInjector(_options.Seed * 7919);
        _plugs = new ModulePlugs(_modules, _options);

        var ids = _modules.Select(m => m.Id).ToArray();
        var motorCounts = _modules.Select(m => (byte)Math.Max(1, m.Motors.Count == 0 ? 1 : m.Motors.Max(x => x.Channel) + 1)).ToArray();
        fixed (byte* pi = ids, pm = motorCounts)
        {
            // From the factory, nothing is written: every module keeps the firmware's default ID.
            _bus = FirmwareHost.BusCreate(ids.Length, _options.Factory ? null : pi, pm);
        }

        if (_bus == 0)
        {
            throw new InvalidOperationException("rcfw_bus_create refused the module layout");
        }

        // Modules leave the factory at the control table's default baud; commissioning moves them to BaudRate.
        FirmwareHost.Check(FirmwareHost.BusSetBaud(_bus, (uint)FactoryBaud), "rcfw_bus_set_baud");
        _byteUs = 10e6 / FactoryBaud;
        _axes = new VirtualAxes(robot, _modules, _options);
        foreach (var axis in _axes.All)
        {
            VirtualAxes.SetHall(_bus, axis);
        }

        // Power-on state: sensors valid before the firmware's first ticks.
        _axes.Feed(_bus);
        for (var mi = 0; mi < _modules.Length; mi++)
        {
            FirmwareHost.Check(FirmwareHost.PowerCycle(_bus, mi), "rcfw_power_cycle");
        }

        for (var mi = 0; mi < _modules.Length; mi++)
        {
            if (!_plugs.IsConnected(mi))
            {
                FirmwareHost.Check(FirmwareHost.PowerOff(_bus, mi), "rcfw_power_off"); // still in the box
            }
        }

        if (_options.Commissioned && !_options.Factory)
        {
            VirtualCommissioning.Run(this);
        }
    }

    /// <summary>The robot file.</summary>
    public RobotDefinition Definition { get; }

    /// <summary>The simulated clock.</summary>
    public ManualTimeProvider Clock => _clock;

    /// <summary>Bus speed, bits/s (the modules are commissioned to it).</summary>
    public int BaudRate { get; }

    /// <summary>Baud of a module fresh from the factory (the control table's default baud code).</summary>
    public static int FactoryBaud => ModuleParameters.BaudFromCode((int)ControlTable.Firmware["baud_rate"].Default);

    /// <summary>Every simulated motor, modules in file order, motors in file order.</summary>
    public IReadOnlyList<VirtualAxis> Axes => _axes.All;

    /// <summary>Faults on the wire (host and modules alike).</summary>
    public WireFaults WireFaults
    {
        get => _wire.Faults;
        set => _wire.Faults = value;
    }

    /// <summary>Bytes the wire faults corrupted.</summary>
    public long CorruptedBytes => _wire.CorruptedBytes;

    /// <summary>Bytes the wire faults dropped.</summary>
    public long DroppedBytes => _wire.DroppedBytes;

    /// <summary>Bytes the host sent and received (for wire utilisation).</summary>
    public long WireBytes { get; private set; }

    /// <summary>Times two modules drove the line at once.</summary>
    public int Collisions => FirmwareHost.BusCollisions(_bus);

    /// <summary>Simulated time since the robot was built.</summary>
    public TimeSpan Elapsed => TimeSpan.FromTicks(_nowUs * 10);

    /// <summary>The axis that drives <paramref name="actuator"/> of arm <paramref name="arm"/>.</summary>
    /// <exception cref="KeyNotFoundException">No module drives it.</exception>
    public VirtualAxis Axis(int arm, string actuator) =>
        _axes.All.FirstOrDefault(a => a.Config.Arm == arm && a.Config.Actuator.Name == actuator)
        ?? throw new KeyNotFoundException($"no module drives actuator '{actuator}' of arm {arm}");

    /// <summary>The host's end of the bus. Reads run the simulation forward on its clock.</summary>
    public IByteLink OpenLink() => new VirtualLink(this);

    /// <summary>Runs the simulation for <paramref name="duration"/> with no host traffic.</summary>
    public void Advance(TimeSpan duration) => AdvanceTo(_nowUs + (long)Math.Ceiling(duration.TotalMicroseconds));

    /// <summary>Resets module <paramref name="moduleId"/> (cause: brown-out, as cautery EMI does) at <paramref name="at"/> after construction.</summary>
    public void ScheduleReset(byte moduleId, TimeSpan at, byte cause = FirmwareHost.ResetBrownOut)
        => _moduleEvents.Reset((long)at.TotalMicroseconds, _plugs.IndexOf(moduleId), cause);

    /// <summary>Switches module <paramref name="moduleId"/> off and on (RAM lost, FRAM kept).</summary>
    /// <exception cref="InvalidOperationException">The module is not plugged in (<see cref="VirtualRobotOptions.Factory"/>).</exception>
    public void PowerCycle(byte moduleId) => FirmwareHost.Check(FirmwareHost.PowerCycle(_bus, _plugs.ConnectedIndex(moduleId, "power-cycle")), "rcfw_power_cycle");

    /// <summary>
    /// Switches <paramref name="axis"/>'s module off, turns the axis by hand to <paramref name="outputRad"/> (its
    /// firmware counts no Hall edges meanwhile) and switches the module on again: it resumes the position it saved,
    /// which no longer matches the joint, and its pot tells (pot mismatch).
    /// </summary>
    /// <exception cref="ArgumentException">The axis belongs to another robot, or the angle is not finite.</exception>
    public void TurnWhileOff(VirtualAxis axis, double outputRad)
    {
        ArgumentNullException.ThrowIfNull(axis);
        if (Array.IndexOf(_axes.All, axis) < 0)
        {
            throw new ArgumentException($"axis {axis.Config.FullName} is not part of this virtual robot", nameof(axis));
        }

        if (!double.IsFinite(outputRad))
        {
            throw new ArgumentException($"the angle to turn {axis.Config.FullName} to must be finite", nameof(outputRad));
        }

        _ = _plugs.ConnectedIndex(axis.Config.ModuleId, "turn while off");
        axis.Model.Reset(outputRad);
        axis.LastSector = VirtualAxes.Sector(axis);
        // The Hall edge this causes reaches firmware that is about to lose its RAM: the power cycle restarts it from
        // FRAM (saved no later than the last simulated millisecond), reading the sensors as they are now.
        VirtualAxes.SetHall(_bus, axis);
        _axes.Feed(_bus);
        FirmwareHost.Check(FirmwareHost.PowerCycle(_bus, axis.ModuleIndex), "rcfw_power_cycle");
    }

    /// <summary>Reads bytes of module <paramref name="moduleId"/>'s control table directly (not over the bus).</summary>
    public void PeekTable(byte moduleId, ushort address, Span<byte> destination)
    {
        fixed (byte* p = destination)
        {
            FirmwareHost.Check(FirmwareHost.PeekTable(_bus, _plugs.IndexOf(moduleId), address, p, destination.Length), "rcfw_peek_table");
        }
    }

    /// <summary>
    /// Breaks module <paramref name="moduleId"/>'s transmit line at <paramref name="at"/> after construction: from then
    /// on its replies never reach the bus (the host hears nothing from it, and the modules after it in a chained
    /// FAST/SYNC/BULK READ wait for it in vain), while it still hears and obeys the host. The fault of
    /// <c>--inject silent=</c>.
    /// </summary>
    public void ScheduleTransmitBreak(byte moduleId, TimeSpan at) =>
        _moduleEvents.BreakLine((long)at.TotalMicroseconds, _plugs.IndexOf(moduleId));

    /// <summary>
    /// Writes <paramref name="data"/> into module <paramref name="moduleId"/>'s control table at
    /// <paramref name="address"/> through the module's own write checks, without a frame on the bus: a write that did
    /// not come from this host (e.g. a stray frame). Returns the protocol error the module gave (0: applied).
    /// </summary>
    public int WriteTable(byte moduleId, ushort address, ReadOnlySpan<byte> data)
    {
        fixed (byte* p = data)
        {
            return FirmwareHost.Check(FirmwareHost.TableWrite(_bus, _plugs.IndexOf(moduleId), address, p, data.Length), "rcfw_table_write");
        }
    }

    /// <inheritdoc />
    public void Dispose()
    {
        var bus = Interlocked.Exchange(ref _bus, 0);
        if (bus != 0)
        {
            FirmwareHost.BusDestroy(bus);
        }
    }

    internal void HostWrite(ReadOnlySpan<byte> data)
    {
        CatchUpWithClock();
        if (_hostFreeUs > _nowUs)
        {
            AdvanceTo(_hostFreeUs); // the previous frame is still leaving the host's UART
        }

        var n = _wire.Apply(data, _scratch);
        WireBytes += data.Length;
        fixed (byte* p = _scratch)
        {
            FirmwareHost.Check(FirmwareHost.BusWrite(_bus, p, n), "rcfw_bus_write");
        }

        _hostFreeUs = _nowUs + (long)Math.Ceiling(data.Length * _byteUs);
    }

    internal int HostRead(Span<byte> destination, TimeSpan timeout)
    {
        CatchUpWithClock();
        var deadline = _nowUs + (long)Math.Ceiling(timeout.TotalMicroseconds);
        while (true)
        {
            // Let a reply that is streaming in finish before handing it over: the host acts on whole frames only.
            var pending = FirmwareHost.BusPending(_bus);
            if (pending > 0 && _nowUs < deadline)
            {
                AdvanceTo(Math.Min(deadline, _nowUs + Math.Max(1, (long)Math.Ceiling(pending * _byteUs))));
                continue;
            }

            var n = TakeHostBytes(destination);
            if (n > 0 || _nowUs >= deadline)
            {
                return n;
            }

            AdvanceTo(deadline);
        }
    }

    internal void HostDiscard() => TakeHostBytes(_scratch);

    private int TakeHostBytes(Span<byte> destination)
    {
        int n;
        fixed (byte* p = _scratch)
        {
            n = FirmwareHost.BusRead(_bus, p, Math.Min(destination.Length, _scratch.Length));
        }

        WireBytes += n;
        return _wire.Apply(_scratch.AsSpan(0, n), destination);
    }

    private void CatchUpWithClock()
    {
        var clockUs = (_clock.GetTimestamp() - _clockOrigin) / 10;
        if (clockUs > _nowUs)
        {
            AdvanceTo(clockUs);
        }
    }

    private void AdvanceTo(long targetUs)
    {
        while (_nowUs < targetUs)
        {
            var next = Math.Min(targetUs, _physicsUs + _physicsStepUs);
            if (_moduleEvents.NextUs < next)
            {
                next = Math.Max(_nowUs, _moduleEvents.NextUs);
            }

            if (next > _nowUs)
            {
                FirmwareHost.Check(FirmwareHost.AdvanceUs(_bus, (uint)(next - _nowUs)), "rcfw_advance_us");
                _nowUs = next;
            }

            if (_nowUs >= _physicsUs + _physicsStepUs)
            {
                _axes.Step(_bus, (_nowUs - _physicsUs) * 1e-6);
                _physicsUs = _nowUs;
            }

            _moduleEvents.FireDue(_bus, _nowUs);
        }

        _clock.SetTimestamp(_clockOrigin + (_nowUs * 10));
    }
}
