using System.Text.Json;

namespace RobotControl.Definitions.Json;

/// <summary>
/// Reads the fields of one JSON object while tracking JSON paths, adding problems to a <see cref="JsonProblemSink"/>
/// instead of throwing, and reporting unknown fields. The one JSON reader of robot files, graph files and plug-in
/// settings; <see cref="Wording"/> keeps each format's messages.
/// </summary>
public sealed class JsonFieldReader
{
    private readonly JsonElement _element;
    private readonly HashSet<string> _seen = new(StringComparer.Ordinal);

    /// <summary>A reader of <paramref name="element"/>, found at <paramref name="path"/> (empty for a document read on its own).</summary>
    public JsonFieldReader(JsonProblemSink sink, JsonElement element, string path, JsonWording wording = JsonWording.Data)
    {
        ArgumentNullException.ThrowIfNull(sink);
        ArgumentNullException.ThrowIfNull(path);
        Sink = sink;
        _element = element;
        Path = path;
        Wording = wording;
    }

    /// <summary>Where problems go.</summary>
    public JsonProblemSink Sink { get; }

    /// <summary>The JSON path of the object read.</summary>
    public string Path { get; }

    /// <summary>How problems are worded.</summary>
    public JsonWording Wording { get; }

    /// <summary>True when the element is a JSON object.</summary>
    public bool IsObject => _element.ValueKind == JsonValueKind.Object;

    /// <summary>The JSON path of field <paramref name="name"/>.</summary>
    public string FieldPath(string name) => Path.Length == 0 ? name : $"{Path}.{name}";

    /// <summary>True when the field is present and not null.</summary>
    public bool Has(string name) => IsObject && _element.TryGetProperty(name, out var v) && v.ValueKind != JsonValueKind.Null;

    /// <summary>The field's value as it stands (marking it read), or null when absent; reports it missing when required.</summary>
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

    /// <summary>A required number (NaN when absent or invalid).</summary>
    public double Number(string name, double? min = null, double? max = null, bool allowNull = false) =>
        NumberOrNull(name, min, max, required: true, allowNull) ?? double.NaN;

    /// <summary>A number, or null when absent or null (allowed or not).</summary>
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

    /// <summary>Reads <paramref name="v"/> as a finite number within the bounds; NaN (and a problem) otherwise.</summary>
    public double ReadNumber(JsonElement v, string path, double? min = null, double? max = null)
    {
        double value;
        if (v.ValueKind == JsonValueKind.Number)
        {
            value = v.GetDouble();
        }
        else if (Wording == JsonWording.Data && v.ValueKind == JsonValueKind.String && v.GetString() is "NaN" or "Infinity" or "-Infinity" or "nan" or "inf")
        {
            Sink.Add(path, $"is {v.GetString()}; a finite number is required");
            return double.NaN;
        }
        else
        {
            Sink.Add(path, WrongKind("a number", v));
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

    /// <summary>A required whole number within min..max (min when absent or invalid).</summary>
    public int Integer(string name, int min, int max) => IntegerOrNull(name, min, max) ?? min;

    /// <summary>A whole number within min..max (not null), or null when absent (reported when required) or not a number.</summary>
    public int? IntegerOrNull(string name, int min, int max, bool required = true)
    {
        if (NumberOrNull(name, min, max, required, allowNull: false) is not { } value || !double.IsFinite(value))
        {
            return null;
        }

        if (value != Math.Floor(value))
        {
            Sink.Add(FieldPath(name), $"is {value}; must be a whole number");
        }

        return (int)value;
    }

    /// <summary>Reads <paramref name="v"/> as a 32-bit integer; null (and a problem) otherwise.</summary>
    public int? ReadInteger(JsonElement v, string path)
    {
        if (v.ValueKind == JsonValueKind.Number && v.TryGetInt32(out var i))
        {
            return i;
        }

        Sink.Add(path, WrongKind("an integer", v));
        return null;
    }

    /// <summary>
    /// A required string; empty when absent, null, blank or of another kind, each reported (Data wording: "missing
    /// field", "must not be empty"; Brief wording: "is required" for all three).
    /// </summary>
    public string String(string name)
    {
        if (Wording == JsonWording.Brief)
        {
            var path = FieldPath(name);
            var value = StringOrNull(name);
            if (string.IsNullOrWhiteSpace(value) && !Sink.HasProblemAt(path))
            {
                Sink.Add(path, "is required");
            }

            return string.IsNullOrWhiteSpace(value) ? string.Empty : value;
        }

        return StringOrNull(name, required: true) ?? string.Empty;
    }

    /// <summary>A string, or null when absent or null (reported when required).</summary>
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

        var s = ReadString(v, FieldPath(name));
        if (s is not null && required && string.IsNullOrWhiteSpace(s))
        {
            Sink.Add(FieldPath(name), "must not be empty");
        }

        return s;
    }

    /// <summary>Reads <paramref name="v"/> as a string; null (and a problem) otherwise.</summary>
    public string? ReadString(JsonElement v, string path)
    {
        if (v.ValueKind == JsonValueKind.String)
        {
            return v.GetString();
        }

        Sink.Add(path, WrongKind("a string", v));
        return null;
    }

    /// <summary>A required boolean (false when absent or invalid).</summary>
    public bool Boolean(string name)
    {
        var raw = Raw(name, required: true);
        return raw is { } v && (ReadBoolean(v, FieldPath(name)) ?? false);
    }

    /// <summary>Reads <paramref name="v"/> as true or false; null (and a problem) otherwise.</summary>
    public bool? ReadBoolean(JsonElement v, string path)
    {
        if (v.ValueKind is JsonValueKind.True or JsonValueKind.False)
        {
            return v.GetBoolean();
        }

        Sink.Add(path, WrongKind("true or false", v));
        return null;
    }

    /// <summary>A nested object's reader, or null when absent, null (reported when required) or not an object.</summary>
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
            Sink.Add(FieldPath(name), WrongKind("an object", v));
            return null;
        }

        return new JsonFieldReader(Sink, v, FieldPath(name), Wording);
    }

    /// <summary>The items of an array field, or null when absent or not an array.</summary>
    public IReadOnlyList<JsonElement>? Array(string name, bool required = true, bool nonEmpty = false)
    {
        var raw = Raw(name, required);
        if (raw is not { } v)
        {
            return null;
        }

        if (v.ValueKind != JsonValueKind.Array)
        {
            Sink.Add(FieldPath(name), WrongKind("an array", v));
            return null;
        }

        var items = v.EnumerateArray().ToArray();
        if (nonEmpty && items.Length == 0)
        {
            Sink.Add(FieldPath(name), "must not be empty");
        }

        return items;
    }

    /// <summary>Every field, in document order (marking each read).</summary>
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

            var stem = UnitSuffix.Strip(p.Name);
            var expected = _seen.FirstOrDefault(s => UnitSuffix.Strip(s) == stem && s != p.Name);
            Sink.Add(
                FieldPath(p.Name),
                expected is null
                    ? "unknown field"
                    : $"wrong unit: expected '{expected}' (unit '{UnitSuffix.Of(expected)}'), found unit '{UnitSuffix.Of(p.Name)}'");
        }
    }

    /// <summary>Reports every field not among <paramref name="known"/>, listing them.</summary>
    public void RejectFieldsOtherThan(params string[] known)
    {
        ArgumentNullException.ThrowIfNull(known);
        foreach (var (name, _) in Properties().Where(p => !known.Contains(p.Name)))
        {
            Sink.Add(FieldPath(name), $"unknown field (known: {string.Join(", ", known)})");
        }
    }

    /// <summary>A JSON value for a message: <c>the number 5</c>, <c>the string "x"</c>, <c>an array</c>, ...</summary>
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

    /// <summary>The JSON kind of a value in lower case: <c>number</c>, <c>string</c>, <c>null</c>, ...</summary>
    public static string KindName(JsonElement v) => v.ValueKind.ToString().ToLowerInvariant();

    private string WrongKind(string expected, JsonElement found) =>
        Wording == JsonWording.Brief ? $"expected {expected}, found {KindName(found)}" : $"must be {expected}, found {Describe(found)}";

    private string MissingMessage(string name)
    {
        if (Wording == JsonWording.Brief)
        {
            return "is required";
        }

        if (!IsObject)
        {
            return "missing field";
        }

        var stem = UnitSuffix.Strip(name);
        foreach (var p in _element.EnumerateObject())
        {
            if (p.Name != name && UnitSuffix.Strip(p.Name) == stem && UnitSuffix.Of(p.Name).Length > 0)
            {
                _seen.Add(p.Name);
                return $"missing field; found '{p.Name}' in unit '{UnitSuffix.Of(p.Name)}' but the unit must be '{UnitSuffix.Of(name)}' (wrong unit)";
            }
        }

        return "missing field";
    }
}
