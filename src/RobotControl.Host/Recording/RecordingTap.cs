using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Exchange;
using RobotControl.Robot.Control;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.Loop;
using RobotControl.Runtime.Robot;

namespace RobotControl.Host.Recording;

/// <summary>
/// The recorder's side on the loop thread: after each tick it copies one row (<see cref="RecordingLayout"/>) into the
/// SDK's lock-free <see cref="SampleRing"/>: no lock, no allocation, no I/O; a full ring drops the row and counts it
/// (the loop never waits for the disk). Does nothing until a recorder binds it (<see cref="Bind"/>), so it can be built
/// with the loop and switched on later (the console's record button).
/// </summary>
public sealed class RecordingTap : ITickObserver
{
    private readonly RobotNode _node;
    private readonly IRobotPort _port;
    private volatile Bound? _bound;

    /// <summary>Creates a tap on the robot node and the robot, chained before <paramref name="next"/>.</summary>
    public RecordingTap(RobotNode node, IRobotPort port, ITickObserver? next = null)
    {
        ArgumentNullException.ThrowIfNull(node);
        ArgumentNullException.ThrowIfNull(port);
        _node = node;
        _port = port;
        Next = next;
    }

    /// <summary>The observer called after this one.</summary>
    public ITickObserver? Next { get; }

    /// <summary>Rows dropped because the writer fell behind (since the last bind).</summary>
    public long Dropped => _bound?.Ring.Dropped ?? 0;

    /// <inheritdoc />
    public void AfterTick(in TickContext context)
    {
        if (_bound is { } bound)
        {
            Copy(bound, context);
        }

        Next?.AfterTick(context);
    }

    /// <summary>Starts copying rows of <paramref name="layout"/> from <paramref name="program"/> into <paramref name="ring"/> (any thread).</summary>
    internal void Bind(RecordingLayout layout, GraphProgram program, SampleRing ring) => _bound = new Bound(layout, program, ring);

    /// <summary>Stops copying (any thread); the loop's next tick sees it.</summary>
    internal void Unbind() => _bound = null;

    private void Copy(Bound bound, in TickContext context)
    {
        var row = bound.Ring.BeginWrite();
        if (row.IsEmpty)
        {
            return;
        }

        var layout = bound.Layout;
        row[0] = context.Elapsed.Ticks * 100.0; // ns of loop time, exact below 2^53
        bound.Program.OutputSignals.Values.CopyTo(row.Slice(1, layout.Outputs.Count));
        var inputs = bound.Program.InputSignals.Values;
        var at = 1 + layout.Outputs.Count;
        foreach (var i in layout.DeviceInputs)
        {
            row[at++] = inputs[i];
        }

        var joints = layout.Robot.JointCount;
        for (var arm = 0; arm < layout.Arms.Count && arm < _port.ArmCount; arm++)
        {
            var slot = layout.Arms[arm];
            row[slot.Tracked] = _node.TeleopEnabled && _node.CommandedThisTick(arm) ? 1 : 0;
            _node.LastCommanded(arm).CopyTo(row.Slice(slot.Setpoints, joints));
            _port.ReadJointPositions(arm, row.Slice(slot.Positions, joints));
            _port.ReadMotorCurrents(arm, row.Slice(slot.Currents, layout.Robot.Actuators.Count));
        }

        bound.Ring.EndWrite();
    }

    private sealed record Bound(RecordingLayout Layout, GraphProgram Program, SampleRing Ring);
}
