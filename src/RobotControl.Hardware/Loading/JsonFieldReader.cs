using System.Text.Json;

namespace RobotControl.Hardware.Loading;

/// <summary>
/// Reads fields of one JSON object while tracking JSON paths, collecting problems instead of throwing, and
/// reporting unknown fields (including a field whose name carries the wrong unit suffix).
/// </summary>
internal sealed class JsonFieldReader
{
    private static readonly string[] KnownUnitSuffixes =
    [
        "_mm", "_cm", "_m", "_in", "_deg", "_rad", "_mNm", "_Nm", "_rpm", "_rad_s", "_pct", "_ohm", "_A", "_V", "_uH",
        "_ms", "_s", "_g", "_kg", "_g_cm2", "_K_per_W", "_C", "_N", "_mm_s", "_cm2", "_cm3", "_mNm_per_rpm",
        "_rpm_per_V", "_mV_per_rpm", "_mNm_per_A", "_rad_per_s",
    ];

    private readonly JsonElement _element;
    private readonly HashSet<string> _seen = new(StringComparer.Ordinal);

    public JsonFieldReader(DataErrorSink sink, JsonElement element, string path)
    {
        Sink = sink;
        _element = element;
        Path = path;
    }

    public DataErrorSink Sink { get; }

    public string Path { get; }

    public bool IsObject => _element.ValueKind == JsonValueKind.Object;

    public string FieldPath(string name) => $"{Path}.{name}";

    public bool Has(string name) => IsObject && _element.TryGetProperty(name, out var v) && v.ValueKind != JsonValueKind.Null;

    public JsonElement? Raw(string name, bool required)
    {
        _seen.Add(name);
        if (!IsObject)
        {
            return null;
        }

        if (_element.TryGetProperty(name, out var value))
        {
            return value;
        }

        if (required)
        {
            Sink.Add(FieldPath(name), MissingMessage(name));
        }

        return null;
    }

    public double Number(string name, double? min = null, double? max = null, bool allowNull = false) =>
        NumberOrNull(name, min, max, required: true, allowNull) ?? double.NaN;

    public double? NumberOrNull(string name, double? min = null, double? max = null, bool required = true, bool allowNull = true)
    {
        var raw = Raw(name, required);
        if (raw is not { } v)
        {
            return null;
        }

        if (v.ValueKind == JsonValueKind.Null)
        {
            if (!allowNull)
            {
                Sink.Add(FieldPath(name), "must be a number, not null");
            }

            return null;
        }

        return ReadNumber(v, FieldPath(name), min, max);
    }

    public double ReadNumber(JsonElement v, string path, double? min = null, double? max = null)
    {
        double value;
        if (v.ValueKind == JsonValueKind.Number)
        {
            value = v.GetDouble();
        }
        else if (v.ValueKind == JsonValueKind.String && v.GetString() is "NaN" or "Infinity" or "-Infinity" or "nan" or "inf")
        {
            Sink.Add(path, $"is {v.GetString()}; a finite number is required");
            return double.NaN;
        }
        else
        {
            Sink.Add(path, $"must be a number, found {Describe(v)}");
            return double.NaN;
        }

        if (!double.IsFinite(value))
        {
            Sink.Add(path, "must be a finite number");
            return double.NaN;
        }

        if (min is { } lo && value < lo)
        {
            Sink.Add(path, $"is {value}; must be at least {lo}");
        }

        if (max is { } hi && value > hi)
        {
            Sink.Add(path, $"is {value}; must be at most {hi}");
        }

        return value;
    }

    public int Integer(string name, int min, int max)
    {
        var value = Number(name, min, max);
        if (double.IsFinite(value) && value != Math.Floor(value))
        {
            Sink.Add(FieldPath(name), $"is {value}; must be a whole number");
        }

        return double.IsFinite(value) ? (int)value : min;
    }

    public string String(string name) => StringOrNull(name, required: true) ?? string.Empty;

    public string? StringOrNull(string name, bool required = false)
    {
        var raw = Raw(name, required);
        if (raw is not { } v || v.ValueKind == JsonValueKind.Null)
        {
            if (raw is { ValueKind: JsonValueKind.Null } && required)
            {
                Sink.Add(FieldPath(name), "must be a string, not null");
            }

            return null;
        }

        if (v.ValueKind != JsonValueKind.String)
        {
            Sink.Add(FieldPath(name), $"must be a string, found {Describe(v)}");
            return null;
        }

        var s = v.GetString()!;
        if (required && string.IsNullOrWhiteSpace(s))
        {
            Sink.Add(FieldPath(name), "must not be empty");
        }

        return s;
    }

    public bool Boolean(string name)
    {
        var raw = Raw(name, required: true);
        if (raw is not { } v)
        {
            return false;
        }

        if (v.ValueKind is not (JsonValueKind.True or JsonValueKind.False))
        {
            Sink.Add(FieldPath(name), $"must be true or false, found {Describe(v)}");
            return false;
        }

        return v.GetBoolean();
    }

    public JsonFieldReader? Object(string name, bool required = true)
    {
        var raw = Raw(name, required);
        if (raw is not { } v || v.ValueKind == JsonValueKind.Null)
        {
            if (raw is { ValueKind: JsonValueKind.Null } && required)
            {
                Sink.Add(FieldPath(name), "must be an object, not null");
            }

            return null;
        }

        if (v.ValueKind != JsonValueKind.Object)
        {
            Sink.Add(FieldPath(name), $"must be an object, found {Describe(v)}");
            return null;
        }

        return new JsonFieldReader(Sink, v, FieldPath(name));
    }

    public IReadOnlyList<JsonElement>? Array(string name, bool required = true, bool nonEmpty = false)
    {
        var raw = Raw(name, required);
        if (raw is not { } v)
        {
            return null;
        }

        if (v.ValueKind != JsonValueKind.Array)
        {
            Sink.Add(FieldPath(name), $"must be an array, found {Describe(v)}");
            return null;
        }

        var items = v.EnumerateArray().ToArray();
        if (nonEmpty && items.Length == 0)
        {
            Sink.Add(FieldPath(name), "must not be empty");
        }

        return items;
    }

    public IEnumerable<(string Name, JsonElement Value)> Properties()
    {
        if (!IsObject)
        {
            yield break;
        }

        foreach (var p in _element.EnumerateObject())
        {
            _seen.Add(p.Name);
            yield return (p.Name, p.Value);
        }
    }

    /// <summary>Reports every field that was present but never read, naming a unit mismatch where that explains it.</summary>
    public void RejectUnknownFields()
    {
        if (!IsObject)
        {
            return;
        }

        foreach (var p in _element.EnumerateObject())
        {
            if (_seen.Contains(p.Name))
            {
                continue;
            }

            var stem = StripUnit(p.Name);
            var expected = _seen.FirstOrDefault(s => StripUnit(s) == stem && s != p.Name);
            Sink.Add(
                FieldPath(p.Name),
                expected is null
                    ? "unknown field"
                    : $"wrong unit: expected '{expected}' (unit '{UnitOf(expected)}'), found unit '{UnitOf(p.Name)}'");
        }
    }

    public static string Describe(JsonElement v) => v.ValueKind switch
    {
        JsonValueKind.String => $"the string \"{v.GetString()}\"",
        JsonValueKind.Number => $"the number {v.GetRawText()}",
        JsonValueKind.Array => "an array",
        JsonValueKind.Object => "an object",
        JsonValueKind.True or JsonValueKind.False => "a boolean",
        JsonValueKind.Null => "null",
        _ => v.ValueKind.ToString(),
    };

    private string MissingMessage(string name)
    {
        if (!IsObject)
        {
            return "missing field";
        }

        var stem = StripUnit(name);
        foreach (var p in _element.EnumerateObject())
        {
            if (p.Name != name && StripUnit(p.Name) == stem && UnitOf(p.Name).Length > 0)
            {
                _seen.Add(p.Name);
                return $"missing field; found '{p.Name}' in unit '{UnitOf(p.Name)}' but the unit must be '{UnitOf(name)}' (wrong unit)";
            }
        }

        return "missing field";
    }

    private static string StripUnit(string name)
    {
        var best = string.Empty;
        foreach (var suffix in KnownUnitSuffixes)
        {
            if (name.EndsWith(suffix, StringComparison.Ordinal) && suffix.Length > best.Length && name.Length > suffix.Length)
            {
                best = suffix;
            }
        }

        return name[..^best.Length];
    }

    private static string UnitOf(string name) => name[StripUnit(name).Length..].TrimStart('_');
}

/// <summary>Collects problems for one file.</summary>
internal sealed class DataErrorSink(string file)
{
    private readonly List<DataError> _errors = [];

    public string File { get; } = file;

    public IReadOnlyList<DataError> Errors => _errors;

    public void Add(string path, string message) => _errors.Add(new DataError(File, path, message));

    public void ThrowIfAny()
    {
        if (_errors.Count > 0)
        {
            throw new RobotDataException(_errors.ToArray());
        }
    }
}
