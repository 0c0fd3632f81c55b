using System.Text;
using System.Text.Json.Nodes;

namespace RobotControl.Host.Recording;

/// <summary>
/// The JSON Schemas of the recording's channels, made from the recording's layout (signal, joint and actuator names
/// become the properties), and Foxglove's published <c>foxglove.FrameTransforms</c> schema for the tool poses.
/// </summary>
internal static class RecordingSchemas
{
    /// <summary>The schema encoding MCAP names for JSON Schema.</summary>
    public const string Encoding = "jsonschema";

    /// <summary>Graph signals: one object per instance, one number (null when not finite) per port.</summary>
    public static byte[] Signals(IEnumerable<string> names)
    {
        var instances = new JsonObject();
        foreach (var group in names.GroupBy(n => Instance(n).Instance))
        {
            instances[group.Key] = Numbers(group.Select(n => Instance(n).Port));
        }

        return Bytes(Object("Every output signal of the graph, by instance and port", instances));
    }

    /// <summary>An input device: its readings and what the graph sends back to it (forces).</summary>
    public static byte[] Device(IEnumerable<string> readings, IEnumerable<string> sentBack) => Bytes(Object(
        "An input device's readings and the values sent back to it (forces)",
        new JsonObject { ["readings"] = Numbers(readings), ["sent_back"] = Numbers(sentBack) }));

    /// <summary>One arm's joints.</summary>
    public static byte[] Joints(IEnumerable<string> joints, IEnumerable<string> actuators)
    {
        var j = joints.ToList();
        return Bytes(Object(
            "One arm's joint setpoints and positions (rad, the arm's own model) and motor currents (A)",
            new JsonObject
            {
                ["tracking"] = new JsonObject { ["type"] = "boolean", ["description"] = "teleoperation drove the arm this tick (the run report's tracking samples)" },
                ["setpoint_rad"] = Numbers(j),
                ["position_rad"] = Numbers(j),
                ["current_a"] = Numbers(actuators),
            }));
    }

    /// <summary>A run-level transition: from, to, who moved it and why.</summary>
    public static byte[] RunLevel() => Bytes(Object("A run-level transition of the safety supervisor", Strings("from", "to", "source", "reason")));

    /// <summary>A safety trip.</summary>
    public static byte[] Trip()
    {
        var properties = Strings("check", "joint", "unit", "action");
        properties["measured"] = Number();
        properties["limit"] = Number();
        properties["soft"] = new JsonObject { ["type"] = "boolean" };
        return Bytes(Object("A safety trip: the check, what it measured against its limit, the safe state taken", properties));
    }

    /// <summary>An operator command: who and what.</summary>
    public static byte[] OperatorCommand() => Bytes(Object("An operator command", Strings("who", "what")));

    /// <summary>Bus statistics (running totals).</summary>
    public static byte[] Bus() => Bytes(Object("Bus statistics, running totals", NumberProperties(["cycles", "frames", "crc_errors", "timeouts", "retries", "late_replies"])));

    /// <summary>Module status, by bus ID.</summary>
    public static byte[] Modules(IEnumerable<byte> ids)
    {
        var modules = new JsonObject();
        foreach (var id in ids)
        {
            modules[id.ToString(System.Globalization.CultureInfo.InvariantCulture)] = Object(
                "module " + id,
                new JsonObject { ["present"] = new JsonObject { ["type"] = "boolean" }, ["hardware_error_bits"] = Number() });
        }

        return Bytes(Object("Module status by bus ID", modules));
    }

    /// <summary>Foxglove's <c>foxglove.FrameTransforms</c> (JSON encoding): poses of child frames in parent frames, metres and a unit quaternion.</summary>
    public static byte[] FrameTransforms()
    {
        var time = new JsonObject { ["type"] = "object", ["properties"] = new JsonObject { ["sec"] = Integer(), ["nsec"] = Integer() } };
        var vector = new JsonObject { ["type"] = "object", ["properties"] = new JsonObject { ["x"] = Number(), ["y"] = Number(), ["z"] = Number() } };
        var quaternion = new JsonObject { ["type"] = "object", ["properties"] = new JsonObject { ["x"] = Number(), ["y"] = Number(), ["z"] = Number(), ["w"] = Number() } };
        var transform = new JsonObject
        {
            ["type"] = "object",
            ["properties"] = new JsonObject
            {
                ["timestamp"] = time,
                ["parent_frame_id"] = new JsonObject { ["type"] = "string" },
                ["child_frame_id"] = new JsonObject { ["type"] = "string" },
                ["translation"] = vector,
                ["rotation"] = quaternion,
            },
        };
        return Bytes(new JsonObject
        {
            ["title"] = "foxglove.FrameTransforms",
            ["description"] = "An array of FrameTransform messages",
            ["type"] = "object",
            ["properties"] = new JsonObject { ["transforms"] = new JsonObject { ["type"] = "array", ["items"] = transform } },
        });
    }

    /// <summary>Splits <c>instance.port</c> at its first dot.</summary>
    public static (string Instance, string Port) Instance(string signal)
    {
        var dot = signal.IndexOf('.', StringComparison.Ordinal);
        return dot < 0 ? (signal, "value") : (signal[..dot], signal[(dot + 1)..]);
    }

    private static JsonObject Object(string description, JsonObject properties) =>
        new() { ["type"] = "object", ["description"] = description, ["properties"] = properties };

    private static JsonObject Numbers(IEnumerable<string> names) => new() { ["type"] = "object", ["properties"] = NumberProperties(names) };

    private static JsonObject NumberProperties(IEnumerable<string> names)
    {
        var properties = new JsonObject();
        foreach (var name in names)
        {
            properties[name] = Number();
        }

        return properties;
    }

    private static JsonObject Strings(params string[] names)
    {
        var properties = new JsonObject();
        foreach (var name in names)
        {
            properties[name] = new JsonObject { ["type"] = "string" };
        }

        return properties;
    }

    private static JsonObject Number() => new() { ["type"] = new JsonArray("number", "null") };

    private static JsonObject Integer() => new() { ["type"] = "integer" };

    private static byte[] Bytes(JsonObject schema)
    {
        return System.Text.Encoding.UTF8.GetBytes(schema.ToJsonString());
    }
}
