using RobotControl.Bus.Protocol;

namespace RobotControl.Bus.Tests.Protocol;

/// <summary>
/// The control-table reader on a small table written here, whose addresses, runs and byte values are worked out by
/// hand (the firmware's own table is checked against the C side by the shared vectors).
/// </summary>
public sealed class ControlTableTests
{
    // Persistent 0..8: a (u16 at 0, read-only), w (i32 at 2, count 0 read as 1), s (i16 at 6).
    // Volatile 8..20: b (i8, two motors at 8 and 12), big (u32 at 16), odd (size 3 at 13, never decoded).
    private const string Json = """
        {
          "table_size": 20, "max_motors": 2,
          "areas": { "persistent": { "start": 0, "end": 8 }, "volatile": { "start": 8, "end": 20 } },
          "fields": [
            { "name": "b", "address": 8, "size": 1, "type": "i8", "access": "RW", "area": "volatile", "count": 2, "stride": 4,
              "min": -128, "max": 127, "default": 0, "bits": { "on": 0, "alarm": 3 } },
            { "name": "big", "address": 16, "size": 4, "type": "u32", "access": "R", "area": "volatile", "count": 1, "stride": 0,
              "min": 0, "max": 4294967295, "default": 0 },
            { "name": "a", "address": 0, "size": 2, "type": "u16", "access": "R", "area": "persistent", "count": 1, "stride": 0,
              "min": 0, "max": 65535, "default": 7, "unit": "mm", "description": "first field", "codes": { "0": "ok", "5": "bad" } },
            { "name": "w", "address": 2, "size": 4, "type": "i32", "access": "RW", "area": "persistent", "count": 0, "stride": 0,
              "min": -10, "max": 10, "default": 1 },
            { "name": "s", "address": 6, "size": 2, "type": "i16", "access": "W", "area": "persistent", "count": 1, "stride": 0,
              "min": -5, "max": 5, "default": -1 },
            { "name": "odd", "address": 13, "size": 3, "type": "u24", "access": "R", "area": "volatile", "count": 1, "stride": 0,
              "min": 0, "max": 1, "default": 0 }
          ]
        }
        """;

    // Parsed by each test, not once in a static field: a mutant of the reader must meet every test (Stryker runs the
    // mutants of code reached from a static initialiser only once per test process).
    private static ControlTable Table => ControlTable.Parse(Json);

    [Fact]
    public void The_header_and_every_field_attribute_are_read()
    {
        Assert.Equal((20, 2), (Table.TableSize, Table.MaxMotors));
        Assert.Equal((0, 8), Table.PersistentArea);
        Assert.Equal((8, 20), Table.VolatileArea);
        Assert.Equal(["a", "w", "s", "b", "odd", "big"], Table.Fields.Select(f => f.Name)); // by address

        var a = Table["a"];
        Assert.Equal((0, 2, "u16", false, true, 1, 0), (a.Address, a.Size, a.Type, a.Writable, a.Persistent, a.Count, a.Stride));
        Assert.Equal((0.0, 65535.0, 7.0, "mm", "first field"), (a.Min, a.Max, a.Default, a.Unit, a.Description));
        Assert.Equal((true, true, 1, "", ""), (Table["w"].Writable, Table["s"].Writable, Table["w"].Count, Table["w"].Unit, Table["w"].Description));
        Assert.False(Table["b"].Persistent);
        Assert.True(Table.Contains("big"));
        Assert.False(Table.Contains("nope"));
        Assert.Contains("no field 'nope'", Assert.Throws<KeyNotFoundException>(() => Table["nope"]).Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Per_motor_addresses_step_by_the_stride_and_stop_at_the_count()
    {
        var b = Table["b"];
        Assert.Equal((8, 12), (b.At(0), b.At(1)));
        Assert.Equal(2, Table["w"].At());
        Assert.Throws<ArgumentOutOfRangeException>(() => b.At(2));
        Assert.Throws<ArgumentOutOfRangeException>(() => b.At(-1));
    }

    [Fact]
    public void Mapped_runs_join_neighbouring_fields_and_respect_the_bounds()
    {
        // Mapped bytes: 0-7 (a, w, s), 8 (b[0]), 12 (b[1]), 13-15 (odd), 16-19 (big).
        Assert.Equal([(0, 9), (12, 8)], Table.MappedRuns(0, 20));
        Assert.Equal([(3, 2)], Table.MappedRuns(3, 5));
        Assert.Equal([(8, 1), (12, 2)], Table.MappedRuns(8, 14));
        Assert.Empty(Table.MappedRuns(9, 12));
    }

    [Fact]
    public void Values_decode_little_endian_with_the_fields_sign()
    {
        Assert.Equal(-1, Table["b"].Decode([0xFF]));
        Assert.Equal(65534, Table["a"].Decode([0xFE, 0xFF]));
        Assert.Equal(-2, Table["s"].Decode([0xFE, 0xFF]));
        Assert.Equal(-2, Table["w"].Decode([0xFE, 0xFF, 0xFF, 0xFF]));
        Assert.Equal(4294967294L, Table["big"].Decode([0xFE, 0xFF, 0xFF, 0xFF]));
        Assert.Equal(0x12345678, Table["w"].Decode([0x78, 0x56, 0x34, 0x12]));
        Assert.True(Table["s"].Signed);
        Assert.False(Table["big"].Signed);
    }

    [Fact]
    public void Values_encode_little_endian()
    {
        var bytes = new byte[4];
        Table["w"].Encode(-2, bytes);
        Assert.Equal([0xFE, 0xFF, 0xFF, 0xFF], bytes);
        Table["a"].Encode(0x1234, bytes);
        Assert.Equal([0x34, 0x12, 0xFF, 0xFF], bytes);
        Table["b"].Encode(-1, bytes.AsSpan(2));
        Assert.Equal([0x34, 0x12, 0xFF, 0xFF], bytes);
        Table["b"].Encode(5, bytes.AsSpan(3));
        Assert.Equal([0x34, 0x12, 0xFF, 0x05], bytes);
    }

    [Fact]
    public void An_unsupported_size_is_refused_naming_the_field()
    {
        Assert.Contains("odd: unsupported size 3", Assert.Throws<InvalidOperationException>(() => Table["odd"].Decode([1, 2, 3])).Message, StringComparison.Ordinal);
        Assert.Throws<InvalidOperationException>(() => Table["odd"].Encode(1, new byte[3]));
    }

    [Fact]
    public void Bits_and_codes_are_looked_up_by_field()
    {
        Assert.Equal((1, 8), (Table.Bit("b", "on"), Table.Bit("b", "alarm")));
        Assert.Equal(2, Table.Bits("b").Count);
        Assert.Empty(Table.Bits("a"));
        Assert.Contains("defines no bit 'nope'", Assert.Throws<KeyNotFoundException>(() => Table.Bit("b", "nope")).Message, StringComparison.Ordinal);
        Assert.Equal("bad", Table.Codes("a")[5]);
        Assert.Equal("ok", Table.Codes("a")[0]);
        Assert.Empty(Table.Codes("b"));
    }

    [Fact]
    public void A_strided_field_maps_its_instances_only_and_an_unsigned_byte_decodes_above_127()
    {
        // u (u8, 3 motors at 1, 4, 7) and a gap after it: bytes 0, 2, 3, 5, 6, 8, 9 are unmapped.
        var table = ControlTable.Parse("""
            {
              "table_size": 10, "max_motors": 3,
              "areas": { "persistent": { "start": 0, "end": 0 }, "volatile": { "start": 0, "end": 10 } },
              "fields": [
                { "name": "u", "address": 1, "size": 1, "type": "u8", "access": "RW", "area": "volatile", "count": 3, "stride": 3,
                  "min": 0, "max": 255, "default": 0 }
              ]
            }
            """);
        Assert.Equal([(1, 1), (4, 1), (7, 1)], table.MappedRuns(0, 10));
        Assert.Equal(200, table["u"].Decode([200]));
        Assert.False(table["u"].Signed);
    }
}
