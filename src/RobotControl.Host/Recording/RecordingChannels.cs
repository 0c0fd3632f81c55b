using System.Buffers;
using System.Globalization;
using System.Text.Json;
using RobotControl.Host.Recording.Mcap;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Urdf;

namespace RobotControl.Host.Recording;

/// <summary>
/// The recording's channels on an <see cref="McapWriter"/> (JSON messages, each with its JSON Schema) and the
/// encoding of a loop row into their messages: per arm its joints at every recorded tick; the graph's signals, the
/// input devices and the tool poses (<c>foxglove.FrameTransforms</c> on <c>/tf</c>) at the decimated ticks, with the
/// URDF's link frames (<see cref="UrdfLinkFrames"/>, at the measured joints) in the <c>/tf</c> message of the rows
/// asked for, so the file opens in a 3D tool with the recording's URDF. Used by the writer thread only.
/// </summary>
internal sealed class RecordingChannels : IDisposable
{
    private readonly McapWriter _writer;
    private readonly RecordingLayout _layout;
    private readonly ArrayBufferWriter<byte> _buffer = new(1 << 16);
    private readonly Utf8JsonWriter _json;
    private readonly ushort _signals;
    private readonly ushort _transforms;
    private readonly ushort[] _devices;
    private readonly ushort[] _joints;
    private readonly ChainState _measured;
    private readonly ChainState _commanded;
    private readonly UrdfLinkFrames _links;
    private readonly (string Model, string Measured, string Setpoint)[] _toolFrames;
    private readonly string[] _jointNames;
    private readonly string[] _actuatorNames;
    private readonly (string Instance, string Port)[] _signalNames;

    public RecordingChannels(McapWriter writer, RecordingLayout layout, IEnumerable<byte> moduleIds)
    {
        _writer = writer;
        _layout = layout;
        _json = new Utf8JsonWriter(_buffer, new JsonWriterOptions { SkipValidation = true });
        var robot = layout.Robot;
        _jointNames = [.. robot.Joints.Select(j => j.Name)];
        _actuatorNames = [.. robot.Actuators.Select(a => a.Name)];
        _signalNames = [.. layout.Outputs.Select(RecordingSchemas.Instance)];
        _signals = Channel(RecordingTopics.Signals, "robotcontrol.GraphSignals", RecordingSchemas.Signals(layout.Outputs));
        _devices = [.. layout.Devices.Select(d => Channel($"/devices/{d.Name}", "robotcontrol.DeviceSignals", RecordingSchemas.Device(d.ReadingNames, d.SentBackNames)))];
        var jointSchema = writer.AddSchema("robotcontrol.ArmJoints", RecordingSchemas.Encoding, RecordingSchemas.Joints(_jointNames, _actuatorNames));
        _joints = [.. layout.Arms.Select(a => writer.AddChannel(jointSchema, RecordingTopics.Joints(a.Name), "json"))];
        _transforms = Channel(RecordingTopics.Transforms, "foxglove.FrameTransforms", RecordingSchemas.FrameTransforms());
        RunLevel = Channel(RecordingTopics.RunLevel, "robotcontrol.RunLevelTransition", RecordingSchemas.RunLevel());
        Trips = Channel(RecordingTopics.Trips, "robotcontrol.SafetyTrip", RecordingSchemas.Trip());
        Operator = Channel(RecordingTopics.Operator, "robotcontrol.OperatorCommand", RecordingSchemas.OperatorCommand());
        Bus = Channel(RecordingTopics.Bus, "robotcontrol.BusStatistics", RecordingSchemas.Bus());
        Modules = Channel(RecordingTopics.Modules, "robotcontrol.ModuleStatus", RecordingSchemas.Modules(moduleIds));
        var chain = new KinematicChain(robot);
        _measured = chain.CreateState();
        _commanded = chain.CreateState();
        _links = new UrdfLinkFrames(robot);
        _toolFrames = [.. layout.Arms.Select(a => (a.Name + "_model", UrdfExport.ToolLinkName(a.Name) + "_measured", UrdfExport.ToolLinkName(a.Name) + "_setpoint"))];
    }

    public ushort RunLevel { get; }

    public ushort Trips { get; }

    public ushort Operator { get; }

    public ushort Bus { get; }

    public ushort Modules { get; }

    /// <summary>The JSON writer of the next message (reset); call <see cref="Write"/> when done.</summary>
    public Utf8JsonWriter Begin()
    {
        _buffer.ResetWrittenCount();
        _json.Reset(_buffer);
        return _json;
    }

    /// <summary>Writes the message begun with <see cref="Begin"/> on <paramref name="channel"/>.</summary>
    public void Write(ushort channel, ulong logTimeNs)
    {
        _json.Flush();
        _writer.WriteMessage(channel, logTimeNs, _buffer.WrittenSpan);
    }

    /// <summary>
    /// Writes the messages of one loop row at <paramref name="logTimeNs"/>; the graph, devices and poses only when
    /// <paramref name="full"/>, and with the poses the URDF's link frames when <paramref name="links"/>.
    /// </summary>
    public void WriteRow(ReadOnlySpan<double> row, ulong logTimeNs, bool full, bool links)
    {
        for (var arm = 0; arm < _layout.Arms.Count; arm++)
        {
            var slot = _layout.Arms[arm];
            var json = Begin();
            json.WriteStartObject();
            json.WriteBoolean("tracking", row[slot.Tracked] != 0);
            Numbers(json, "setpoint_rad", _jointNames, row.Slice(slot.Setpoints, _jointNames.Length));
            Numbers(json, "position_rad", _jointNames, row.Slice(slot.Positions, _jointNames.Length));
            Numbers(json, "current_a", _actuatorNames, row.Slice(slot.Currents, _actuatorNames.Length));
            json.WriteEndObject();
            Write(_joints[arm], logTimeNs);
        }

        if (!full)
        {
            return;
        }

        WriteSignals(row, logTimeNs);
        for (var d = 0; d < _layout.Devices.Count; d++)
        {
            var device = _layout.Devices[d];
            var json = Begin();
            json.WriteStartObject();
            Picked(json, "readings", device.ReadingNames, device.Readings, row);
            Picked(json, "sent_back", device.SentBackNames, device.SentBack, row);
            json.WriteEndObject();
            Write(_devices[d], logTimeNs);
        }

        WriteTransforms(row, logTimeNs, links);
    }

    private void WriteSignals(ReadOnlySpan<double> row, ulong logTimeNs)
    {
        var json = Begin();
        json.WriteStartObject();
        string? open = null;
        for (var i = 0; i < _signalNames.Length; i++)
        {
            var (instance, port) = _signalNames[i];
            if (!string.Equals(open, instance, StringComparison.Ordinal))
            {
                if (open is not null)
                {
                    json.WriteEndObject();
                }

                json.WriteStartObject(instance);
                open = instance;
            }

            Number(json, port, row[1 + i]);
        }

        if (open is not null)
        {
            json.WriteEndObject();
        }

        json.WriteEndObject();
        Write(_signals, logTimeNs);
    }

    /// <summary>
    /// Each arm's tool, measured and commanded, in the arm's own model frame (<c>{arm}_model</c>), metres; with
    /// <paramref name="links"/>, every URDF link in its parent (from <c>body</c>), at the measured joints.
    /// </summary>
    private void WriteTransforms(ReadOnlySpan<double> row, ulong logTimeNs, bool links)
    {
        var json = Begin();
        json.WriteStartObject();
        json.WriteStartArray("transforms");
        for (var arm = 0; arm < _layout.Arms.Count; arm++)
        {
            var slot = _layout.Arms[arm];
            var (model, measured, setpoint) = _toolFrames[arm];
            _measured.Update(row.Slice(slot.Positions, _jointNames.Length));
            _commanded.Update(row.Slice(slot.Setpoints, _jointNames.Length));
            Transform(json, logTimeNs, model, measured, _measured.ToolPose);
            Transform(json, logTimeNs, model, setpoint, _commanded.ToolPose);
        }

        for (var i = 0; links && i < _links.Count; i++)
        {
            var (position, rotation) = _links.Transform(i, row.Slice(_layout.Arms[_links.Arm(i)].Positions, _jointNames.Length));
            Transform(json, logTimeNs, _links.Parent(i), _links.Child(i), new Pose(position, rotation));
        }

        json.WriteEndArray();
        json.WriteEndObject();
        Write(_transforms, logTimeNs);
    }

    private static void Transform(Utf8JsonWriter json, ulong logTimeNs, string parent, string child, Pose pose)
    {
        json.WriteStartObject();
        json.WriteStartObject("timestamp");
        json.WriteNumber("sec", logTimeNs / 1_000_000_000UL);
        json.WriteNumber("nsec", logTimeNs % 1_000_000_000UL);
        json.WriteEndObject();
        json.WriteString("parent_frame_id", parent);
        json.WriteString("child_frame_id", child);
        json.WriteStartObject("translation");
        Number(json, "x", pose.Position.X * UrdfExport.MetresPerMm);
        Number(json, "y", pose.Position.Y * UrdfExport.MetresPerMm);
        Number(json, "z", pose.Position.Z * UrdfExport.MetresPerMm);
        json.WriteEndObject();
        var (x, y, z, w) = Quaternion(pose.Rotation);
        json.WriteStartObject("rotation");
        Number(json, "x", x);
        Number(json, "y", y);
        Number(json, "z", z);
        Number(json, "w", w);
        json.WriteEndObject();
        json.WriteEndObject();
    }

    /// <summary>The unit quaternion of rotation matrix <paramref name="r"/> (columns X, Y, Z).</summary>
    internal static (double X, double Y, double Z, double W) Quaternion(Rotation3d r)
    {
        double m00 = r.At(0, 0), m11 = r.At(1, 1), m22 = r.At(2, 2);
        var trace = m00 + m11 + m22;
        if (trace > 0)
        {
            var s = Math.Sqrt(trace + 1) * 2;
            return ((r.At(2, 1) - r.At(1, 2)) / s, (r.At(0, 2) - r.At(2, 0)) / s, (r.At(1, 0) - r.At(0, 1)) / s, s / 4);
        }

        if (m00 > m11 && m00 > m22)
        {
            var s = Math.Sqrt(1 + m00 - m11 - m22) * 2;
            return (s / 4, (r.At(0, 1) + r.At(1, 0)) / s, (r.At(0, 2) + r.At(2, 0)) / s, (r.At(2, 1) - r.At(1, 2)) / s);
        }

        if (m11 > m22)
        {
            var s = Math.Sqrt(1 + m11 - m00 - m22) * 2;
            return ((r.At(0, 1) + r.At(1, 0)) / s, s / 4, (r.At(1, 2) + r.At(2, 1)) / s, (r.At(0, 2) - r.At(2, 0)) / s);
        }

        var t = Math.Sqrt(1 + m22 - m00 - m11) * 2;
        return ((r.At(0, 2) + r.At(2, 0)) / t, (r.At(1, 2) + r.At(2, 1)) / t, t / 4, (r.At(1, 0) - r.At(0, 1)) / t);
    }

    private ushort Channel(string topic, string schemaName, byte[] schema) =>
        _writer.AddChannel(_writer.AddSchema(schemaName, RecordingSchemas.Encoding, schema), topic, "json");

    private static void Numbers(Utf8JsonWriter json, string name, string[] names, ReadOnlySpan<double> values)
    {
        json.WriteStartObject(name);
        for (var i = 0; i < names.Length; i++)
        {
            Number(json, names[i], values[i]);
        }

        json.WriteEndObject();
    }

    private static void Picked(Utf8JsonWriter json, string name, string[] names, int[] at, ReadOnlySpan<double> row)
    {
        json.WriteStartObject(name);
        for (var i = 0; i < names.Length; i++)
        {
            Number(json, names[i], row[at[i]]);
        }

        json.WriteEndObject();
    }

    /// <summary>A number, or null when it is not finite (JSON has no NaN).</summary>
    internal static void Number(Utf8JsonWriter json, string name, double value)
    {
        if (double.IsFinite(value))
        {
            json.WriteNumber(name, value);
        }
        else
        {
            json.WriteNull(name);
        }
    }

    /// <inheritdoc />
    public void Dispose() => _json.Dispose();

    /// <summary>The text of a bus ID as the module status names it.</summary>
    internal static string Id(byte id) => id.ToString(CultureInfo.InvariantCulture);
}
