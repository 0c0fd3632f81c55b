using System.Text.Json;

namespace RobotControl.Bus.Protocol;

/// <summary>
/// The modules' control table as the firmware defines it (firmware/protocol/control-table.json, embedded in this
/// assembly): the single source of every address. Look fields up once (at construction of whatever uses them),
/// never per cycle.
/// </summary>
public sealed class ControlTable
{
    private const string ResourceName = "RobotControl.Bus.Protocol.control-table.json";
    private static readonly Lazy<ControlTable> s_firmware = new(LoadEmbedded);
    private readonly Dictionary<string, ControlTableField> _fields;
    private Dictionary<string, IReadOnlyDictionary<string, int>> _bits = [];
    private Dictionary<string, IReadOnlyDictionary<int, string>> _codes = [];

    private ControlTable(int tableSize, int maxMotors, (int Start, int End) persistent, (int Start, int End) volatileArea, IReadOnlyList<ControlTableField> fields)
    {
        TableSize = tableSize;
        MaxMotors = maxMotors;
        PersistentArea = persistent;
        VolatileArea = volatileArea;
        Fields = fields;
        _fields = fields.ToDictionary(f => f.Name, StringComparer.Ordinal);
    }

    /// <summary>The table the firmware in this repository defines.</summary>
    /// <exception cref="InvalidOperationException">The definition was not embedded (firmware/protocol/control-table.json missing at build time).</exception>
    public static ControlTable Firmware => s_firmware.Value;

    /// <summary>Bytes in the table.</summary>
    public int TableSize { get; }

    /// <summary>Most motors a module drives.</summary>
    public int MaxMotors { get; }

    /// <summary>Address range [start, end) kept in FRAM.</summary>
    public (int Start, int End) PersistentArea { get; }

    /// <summary>Address range [start, end) in RAM.</summary>
    public (int Start, int End) VolatileArea { get; }

    /// <summary>Every field in address order.</summary>
    public IReadOnlyList<ControlTableField> Fields { get; }

    /// <summary>The field named <paramref name="name"/>.</summary>
    /// <exception cref="KeyNotFoundException">The firmware defines no such field.</exception>
    public ControlTableField this[string name] =>
        _fields.TryGetValue(name, out var f) ? f : throw new KeyNotFoundException($"the firmware's control table has no field '{name}'");

    /// <summary>
    /// The runs of bytes in <paramref name="start"/>..<paramref name="end"/> (exclusive) that belong to a field, as
    /// (address, length): a module refuses a read that covers an unmapped byte (access error).
    /// </summary>
    public IReadOnlyList<(int Address, int Length)> MappedRuns(int start, int end)
    {
        var mapped = new bool[TableSize];
        foreach (var f in Fields)
        {
            for (var k = 0; k < f.Count; k++)
            {
                mapped.AsSpan(f.Address + (k * f.Stride), f.Size).Fill(true);
            }
        }

        var runs = new List<(int, int)>();
        for (var a = start; a < end;)
        {
            if (!mapped[a])
            {
                a++;
                continue;
            }

            var b = a;
            while (b < end && mapped[b])
            {
                b++;
            }

            runs.Add((a, b - a));
            a = b;
        }

        return runs;
    }

    /// <summary>For a bit field (e.g. <c>hardware_error_status</c>): each named bit's position, as the definition's <c>bits</c> give them; empty otherwise.</summary>
    public IReadOnlyDictionary<string, int> Bits(string field) =>
        _bits.TryGetValue(field, out var b) ? b : new Dictionary<string, int>(StringComparer.Ordinal);

    /// <summary>The mask of bit <paramref name="bit"/> of field <paramref name="field"/>.</summary>
    /// <exception cref="KeyNotFoundException">The definition names no such bit.</exception>
    public int Bit(string field, string bit) =>
        Bits(field).TryGetValue(bit, out var at) ? 1 << at : throw new KeyNotFoundException($"the control table's field '{field}' defines no bit '{bit}'");

    /// <summary>For a code field (e.g. <c>reset_cause</c>): each code's name, as the definition's <c>codes</c> give them; empty otherwise.</summary>
    public IReadOnlyDictionary<int, string> Codes(string field) =>
        _codes.TryGetValue(field, out var c) ? c : new Dictionary<int, string>();

    /// <summary>True when the firmware defines <paramref name="name"/>.</summary>
    public bool Contains(string name) => _fields.ContainsKey(name);

    /// <summary>Parses a control-table definition.</summary>
    /// <exception cref="JsonException">The text is not a valid definition.</exception>
    public static ControlTable Parse(string json)
    {
        using var doc = JsonDocument.Parse(json);
        var root = doc.RootElement;
        var areas = root.GetProperty("areas");
        var persistent = areas.GetProperty("persistent");
        var volatileArea = areas.GetProperty("volatile");
        var fields = new List<ControlTableField>();
        var bits = new Dictionary<string, IReadOnlyDictionary<string, int>>(StringComparer.Ordinal);
        var codes = new Dictionary<string, IReadOnlyDictionary<int, string>>(StringComparer.Ordinal);
        foreach (var f in root.GetProperty("fields").EnumerateArray())
        {
            fields.Add(new ControlTableField(
                f.GetProperty("name").GetString()!,
                f.GetProperty("address").GetInt32(),
                f.GetProperty("size").GetInt32(),
                f.GetProperty("type").GetString()!,
                f.GetProperty("access").GetString()!.Contains('W', StringComparison.Ordinal),
                f.GetProperty("area").GetString() == "persistent",
                Math.Max(1, f.GetProperty("count").GetInt32()),
                f.GetProperty("stride").GetInt32(),
                f.GetProperty("min").GetDouble(),
                f.GetProperty("max").GetDouble(),
                f.GetProperty("default").GetDouble(),
                f.TryGetProperty("unit", out var u) ? u.GetString() ?? string.Empty : string.Empty,
                f.TryGetProperty("description", out var d) ? d.GetString() ?? string.Empty : string.Empty)
            {
                ZeroDisables = f.TryGetProperty("zero_disables", out var z) ? z.GetString() : null,
            });
            var name = fields[^1].Name;
            if (f.TryGetProperty("bits", out var b))
            {
                bits[name] = b.EnumerateObject().ToDictionary(x => x.Name, x => x.Value.GetInt32(), StringComparer.Ordinal);
            }

            if (f.TryGetProperty("codes", out var c))
            {
                codes[name] = c.EnumerateObject().ToDictionary(x => int.Parse(x.Name, System.Globalization.CultureInfo.InvariantCulture), x => x.Value.GetString() ?? string.Empty);
            }
        }

        return new ControlTable(
            root.GetProperty("table_size").GetInt32(),
            root.GetProperty("max_motors").GetInt32(),
            (persistent.GetProperty("start").GetInt32(), persistent.GetProperty("end").GetInt32()),
            (volatileArea.GetProperty("start").GetInt32(), volatileArea.GetProperty("end").GetInt32()),
            fields.OrderBy(f => f.Address).ToArray())
        {
            _bits = bits,
            _codes = codes,
        };
    }

    private static ControlTable LoadEmbedded()
    {
        using var stream = typeof(ControlTable).Assembly.GetManifestResourceStream(ResourceName)
            ?? throw new InvalidOperationException("the firmware's control table was not embedded: firmware/protocol/control-table.json was missing when RobotControl.Bus was built");
        using var reader = new StreamReader(stream);
        return Parse(reader.ReadToEnd());
    }
}

/// <summary>One field of the control table; per-motor fields repeat <see cref="Count"/> times every <see cref="Stride"/> bytes.</summary>
/// <param name="Name">Field name.</param>
/// <param name="Address">Address of the first (motor 0) instance.</param>
/// <param name="Size">Bytes per instance.</param>
/// <param name="Type">u8, u16, u32, i16 or i32.</param>
/// <param name="Writable">True when the host may write it.</param>
/// <param name="Persistent">True when it is kept in FRAM.</param>
/// <param name="Count">Instances (1, or one per motor).</param>
/// <param name="Stride">Bytes from one instance to the next.</param>
/// <param name="Min">Smallest accepted value.</param>
/// <param name="Max">Largest accepted value.</param>
/// <param name="Default">Factory value.</param>
/// <param name="Unit">Unit as documented.</param>
/// <param name="Description">What the field means.</param>
public sealed record ControlTableField(
    string Name, int Address, int Size, string Type, bool Writable, bool Persistent, int Count, int Stride,
    double Min, double Max, double Default, string Unit, string Description)
{
    /// <summary>Address of instance <paramref name="motor"/>.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The field has no such instance.</exception>
    public ushort At(int motor = 0)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(motor);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(motor, Count);
        return (ushort)(Address + (motor * Stride));
    }

    /// <summary>
    /// The protection that the value 0 switches off (e.g. "the motor's current limit"), as the definition's
    /// <c>zero_disables</c> names it; null when 0 is an ordinary value.
    /// </summary>
    public string? ZeroDisables { get; init; }

    /// <summary>True for i16/i32.</summary>
    public bool Signed => Type.StartsWith('i');

    /// <summary>Decodes one instance's little-endian bytes.</summary>
    public long Decode(ReadOnlySpan<byte> bytes) => Size switch
    {
        1 => Signed ? (sbyte)bytes[0] : bytes[0],
        2 => Signed ? System.Buffers.Binary.BinaryPrimitives.ReadInt16LittleEndian(bytes) : System.Buffers.Binary.BinaryPrimitives.ReadUInt16LittleEndian(bytes),
        4 => Signed ? System.Buffers.Binary.BinaryPrimitives.ReadInt32LittleEndian(bytes) : System.Buffers.Binary.BinaryPrimitives.ReadUInt32LittleEndian(bytes),
        _ => throw new InvalidOperationException($"{Name}: unsupported size {Size}"),
    };

    /// <summary>Encodes <paramref name="value"/> little-endian into <paramref name="bytes"/> (<see cref="Size"/> bytes).</summary>
    public void Encode(long value, Span<byte> bytes)
    {
        switch (Size)
        {
            case 1: bytes[0] = (byte)value; break;
            case 2: System.Buffers.Binary.BinaryPrimitives.WriteUInt16LittleEndian(bytes, (ushort)value); break;
            case 4: System.Buffers.Binary.BinaryPrimitives.WriteUInt32LittleEndian(bytes, (uint)value); break;
            default: throw new InvalidOperationException($"{Name}: unsupported size {Size}");
        }
    }
}
