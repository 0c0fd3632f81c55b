using RobotControl.Definitions.Model;
using RobotControl.Plugins.Sdk.Faults;
using RobotControl.Runtime.GraphFiles;

namespace RobotControl.Host.Recording;

/// <summary>
/// The row the loop thread copies into the recorder's ring each recorded tick, laid out once from the graph and the
/// robot file: the loop time (ns), every output signal of the graph, the input signals of the graph's input devices
/// (the forces sent back to a Touch), and per arm whether teleoperation drove it this tick, its joint setpoints, its
/// joint positions and its motor currents.
/// </summary>
internal sealed class RecordingLayout
{
    public RecordingLayout(LoadedGraph loaded)
    {
        ArgumentNullException.ThrowIfNull(loaded);
        Robot = loaded.Robot ?? throw new InvalidOperationException($"{loaded.Path}: the graph names no robot file");
        Outputs = loaded.Program.OutputSignals.Names;
        var inputs = loaded.Program.InputSignals.Names;
        var offset = 1 + Outputs.Count;
        var devices = new List<DeviceSlot>();
        var deviceInputs = new List<int>();
        foreach (var device in loaded.Graph.Instances.Where(p => p is IFaultInjectable))
        {
            var prefix = device.Name + ".";
            var outs = Enumerable.Range(0, Outputs.Count).Where(i => Outputs[i].StartsWith(prefix, StringComparison.Ordinal)).ToArray();
            var ins = Enumerable.Range(0, inputs.Count).Where(i => inputs[i].StartsWith(prefix, StringComparison.Ordinal)).ToArray();
            devices.Add(new DeviceSlot(device.Name, [.. outs.Select(i => 1 + i)], [.. ins.Select(i => offset + deviceInputs.Count + Array.IndexOf(ins, i))], [.. outs.Select(i => Outputs[i][prefix.Length..])], [.. ins.Select(i => inputs[i][prefix.Length..])]));
            deviceInputs.AddRange(ins);
        }

        Devices = devices;
        DeviceInputs = [.. deviceInputs];
        offset += DeviceInputs.Length;
        var joints = Robot.JointCount;
        var actuators = Robot.Actuators.Count;
        var arms = new List<ArmSlot>();
        foreach (var arm in Robot.Arms)
        {
            arms.Add(new ArmSlot(arm.Name, offset, offset + 1, offset + 1 + joints, offset + 1 + (2 * joints)));
            offset += 1 + (2 * joints) + actuators;
        }

        Arms = arms;
        Width = offset;
    }

    /// <summary>The robot file.</summary>
    public RobotDefinition Robot { get; }

    /// <summary>Every output signal (<c>instance.port</c>), at row index 1 + i.</summary>
    public IReadOnlyList<string> Outputs { get; }

    /// <summary>Indexes into the graph's input signals of the devices' inputs, in row order after the outputs.</summary>
    public int[] DeviceInputs { get; }

    /// <summary>The input devices (instances with the SDK's device-fault seam): where their readings and what is sent back sit in a row.</summary>
    public IReadOnlyList<DeviceSlot> Devices { get; }

    /// <summary>Per arm (robot-file order): where its values sit in a row.</summary>
    public IReadOnlyList<ArmSlot> Arms { get; }

    /// <summary>Values per row.</summary>
    public int Width { get; }

    /// <summary>Where one arm's values sit in a row.</summary>
    /// <param name="Name">The arm's name in the robot file.</param>
    /// <param name="Tracked">1 when teleoperation drove the arm this tick (the tracking meter's samples), else 0.</param>
    /// <param name="Setpoints">First of the joint setpoints (rad, the arm's own model).</param>
    /// <param name="Positions">First of the joint positions the modules reported (rad).</param>
    /// <param name="Currents">First of the motor currents (A), one per actuator.</param>
    internal sealed record ArmSlot(string Name, int Tracked, int Setpoints, int Positions, int Currents);

    /// <summary>Where one input device's values sit in a row.</summary>
    internal sealed record DeviceSlot(string Name, int[] Readings, int[] SentBack, string[] ReadingNames, string[] SentBackNames);
}
