using System.Collections.Concurrent;
using System.Globalization;
using System.Reflection;
using System.Text.Json;
using RobotControl.Definitions.Json;

namespace RobotControl.Plugins.Sdk.Settings;

/// <summary>
/// The settings of one <see cref="PluginSettings"/> type, found by reflection: read from and written to JSON (snake_case
/// names), validated from the <see cref="SettingAttribute"/>s plus <see cref="PluginSettings.CheckConsistency"/>.
/// Cached per type; thread-safe.
/// </summary>
public sealed class SettingsSchema
{
    private static readonly ConcurrentDictionary<Type, SettingsSchema> Cache = new();
    private readonly Dictionary<string, SettingDescriptor> _byName;

    private SettingsSchema(Type type)
    {
        SettingsType = type;
        var defaults = (PluginSettings)Activator.CreateInstance(type)!;
        var settings = new List<SettingDescriptor>();
        foreach (var property in type.GetProperties(BindingFlags.Public | BindingFlags.Instance))
        {
            if (property.GetCustomAttribute<SettingAttribute>() is not { } attribute)
            {
                continue;
            }

            if (!property.CanWrite)
            {
                throw new InvalidOperationException($"{type.Name}.{property.Name}: a setting needs an init or set accessor");
            }

            var kind = KindOf(property.PropertyType)
                ?? throw new InvalidOperationException($"{type.Name}.{property.Name}: settings of type {property.PropertyType.Name} are not supported");
            var enumNames = kind == SettingKind.Choice
                ? Enum.GetNames(property.PropertyType).Select(n => JsonNamingPolicy.SnakeCaseLower.ConvertName(n)).ToArray()
                : [];
            settings.Add(new SettingDescriptor(
                JsonNamingPolicy.SnakeCaseLower.ConvertName(property.Name),
                property,
                kind,
                attribute.Description,
                attribute.Units,
                attribute.Minimum,
                attribute.Maximum,
                attribute.IsFilePath,
                attribute.Required,
                property.GetValue(defaults),
                enumNames));
        }

        Settings = settings;
        _byName = settings.ToDictionary(s => s.JsonName, StringComparer.Ordinal);
    }

    /// <summary>The settings record type.</summary>
    public Type SettingsType { get; }

    /// <summary>Every setting, in declaration order.</summary>
    public IReadOnlyList<SettingDescriptor> Settings { get; }

    /// <summary>The schema of <paramref name="settingsType"/>.</summary>
    /// <exception cref="ArgumentException">The type does not derive from <see cref="PluginSettings"/> or has no parameterless constructor.</exception>
    public static SettingsSchema For(Type settingsType)
    {
        ArgumentNullException.ThrowIfNull(settingsType);
        if (!typeof(PluginSettings).IsAssignableFrom(settingsType) || settingsType.IsAbstract || settingsType.GetConstructor(Type.EmptyTypes) is null)
        {
            throw new ArgumentException($"{settingsType.Name} must be a concrete PluginSettings record with a parameterless constructor", nameof(settingsType));
        }

        return Cache.GetOrAdd(settingsType, static t => new SettingsSchema(t));
    }

    /// <summary>The setting named <paramref name="jsonName"/> in graph files, or null when there is none.</summary>
    public SettingDescriptor? Find(string jsonName)
    {
        ArgumentNullException.ThrowIfNull(jsonName);
        return Settings.FirstOrDefault(s => s.JsonName == jsonName);
    }

    /// <summary>A settings object holding every default.</summary>
    public PluginSettings CreateDefault() => (PluginSettings)Activator.CreateInstance(SettingsType)!;

    /// <summary>Every problem with <paramref name="settings"/> (empty when valid).</summary>
    public IReadOnlyList<JsonProblem> Validate(PluginSettings settings)
    {
        ArgumentNullException.ThrowIfNull(settings);
        var errors = new List<JsonProblem>();
        foreach (var s in Settings)
        {
            var value = s.Property.GetValue(settings);
            switch (s.Kind)
            {
                case SettingKind.Number:
                    CheckRange(s, (double)value!, errors);
                    break;
                case SettingKind.Integer:
                    CheckRange(s, (int)value!, errors);
                    break;
                case SettingKind.Text when s.Required && string.IsNullOrWhiteSpace((string?)value):
                    errors.Add(new JsonProblem(s.JsonName, "is required"));
                    break;
                case SettingKind.Choice when !Enum.IsDefined(s.Property.PropertyType, value!):
                    errors.Add(new JsonProblem(s.JsonName, $"'{value}' is not one of {string.Join(", ", s.EnumNames)}"));
                    break;
                default:
                    break;
            }
        }

        if (errors.Count == 0)
        {
            errors.AddRange(settings.CheckConsistency());
        }

        return errors;
    }

    /// <summary>Throws when <paramref name="settings"/> are invalid.</summary>
    /// <exception cref="SettingsException">Every problem found.</exception>
    public void ThrowIfInvalid(PluginSettings settings, string instanceName)
    {
        var errors = Validate(settings);
        if (errors.Count > 0)
        {
            throw new SettingsException(instanceName, errors);
        }
    }

    /// <summary>
    /// Reads settings from a JSON object: missing settings keep their defaults; unknown names, wrong JSON types and
    /// out-of-range values are added to <paramref name="errors"/> (named by setting). Returns null when any were found.
    /// </summary>
    public PluginSettings? Read(JsonElement json, ICollection<JsonProblem> errors)
    {
        ArgumentNullException.ThrowIfNull(errors);
        var before = errors.Count;
        var settings = CreateDefault();
        if (json.ValueKind is JsonValueKind.Undefined or JsonValueKind.Null)
        {
            return settings;
        }

        if (json.ValueKind != JsonValueKind.Object)
        {
            errors.Add(new JsonProblem("", "expected an object of settings"));
            return null;
        }

        var sink = new JsonProblemSink();
        var reader = new JsonFieldReader(sink, json, "", JsonWording.Brief);
        foreach (var (name, element) in reader.Properties())
        {
            if (!_byName.TryGetValue(name, out var s))
            {
                sink.Add(name, $"unknown setting (known: {string.Join(", ", Settings.Select(x => x.JsonName))})");
                continue;
            }

            if (ReadValue(s, element, reader) is { } value)
            {
                s.Property.SetValue(settings, value);
            }
        }

        foreach (var p in sink.Problems)
        {
            errors.Add(p);
        }

        // Values that did not parse kept their defaults, so validating still finds only real problems.
        foreach (var e in Validate(settings))
        {
            errors.Add(e);
        }

        return errors.Count > before ? null : settings;
    }

    /// <summary>
    /// The settings of <paramref name="settings"/> a graph file holds: those that differ from their
    /// <see cref="SettingDescriptor.DefaultValue"/>, the required ones, and those named in <paramref name="written"/>
    /// (what the file being rewritten gave, even at its default). A file written with them reads back to the same
    /// settings and says only what its author chose.
    /// </summary>
    public IReadOnlyList<SettingDescriptor> Given(PluginSettings settings, IReadOnlyCollection<string>? written = null)
    {
        ArgumentNullException.ThrowIfNull(settings);
        return [.. Settings.Where(s => s.Required || (written?.Contains(s.JsonName) ?? false) || !Equals(s.Property.GetValue(settings), s.DefaultValue))];
    }

    /// <summary>Writes the settings of <paramref name="settings"/> that <see cref="Given"/> names as a JSON object.</summary>
    public void Write(Utf8JsonWriter writer, PluginSettings settings, IReadOnlyCollection<string>? written = null)
    {
        ArgumentNullException.ThrowIfNull(writer);
        writer.WriteStartObject();
        foreach (var s in Given(settings, written))
        {
            var value = s.Property.GetValue(settings);
            writer.WritePropertyName(s.JsonName);
            switch (s.Kind)
            {
                case SettingKind.Number:
                    writer.WriteNumberValue((double)value!);
                    break;
                case SettingKind.Integer:
                    writer.WriteNumberValue((int)value!);
                    break;
                case SettingKind.Boolean:
                    writer.WriteBooleanValue((bool)value!);
                    break;
                case SettingKind.Choice:
                    writer.WriteStringValue(JsonNamingPolicy.SnakeCaseLower.ConvertName(value!.ToString()!));
                    break;
                default:
                    writer.WriteStringValue((string?)value ?? "");
                    break;
            }
        }

        writer.WriteEndObject();
    }

    private static SettingKind? KindOf(Type type) =>
        type == typeof(double) ? SettingKind.Number
        : type == typeof(int) ? SettingKind.Integer
        : type == typeof(bool) ? SettingKind.Boolean
        : type == typeof(string) ? SettingKind.Text
        : type.IsEnum ? SettingKind.Choice
        : null;

    private static object? ReadValue(SettingDescriptor s, JsonElement json, JsonFieldReader reader)
    {
        var path = reader.FieldPath(s.JsonName);
        switch (s.Kind)
        {
            case SettingKind.Number:
                var number = reader.ReadNumber(json, path);
                return double.IsNaN(number) ? null : number;
            case SettingKind.Integer:
                return reader.ReadInteger(json, path);
            case SettingKind.Boolean:
                return reader.ReadBoolean(json, path);
            case SettingKind.Choice:
                if (json.ValueKind != JsonValueKind.String)
                {
                    reader.Sink.Add(path, $"expected a name, found {JsonFieldReader.KindName(json)}");
                    return null;
                }

                var name = json.GetString()!;
                var index = s.EnumNames.ToList().IndexOf(name);
                if (index < 0)
                {
                    reader.Sink.Add(path, $"'{name}' is not one of {string.Join(", ", s.EnumNames)}");
                    return null;
                }

                return Enum.GetValues(s.Property.PropertyType).GetValue(index);
            default:
                return reader.ReadString(json, path);
        }
    }

    private static void CheckRange(SettingDescriptor s, double value, List<JsonProblem> errors)
    {
        if (!double.IsFinite(value))
        {
            errors.Add(new JsonProblem(s.JsonName, "must be a finite number"));
        }
        else if (!s.Accepts(value))
        {
            errors.Add(new JsonProblem(s.JsonName, string.Create(CultureInfo.InvariantCulture, $"{value} is outside {Bound(s.Minimum)}..{Bound(s.Maximum)}{(s.Units.Length > 0 ? " " + s.Units : "")}")));
        }
    }

    private static string Bound(double b) => double.IsNaN(b) ? "" : b.ToString(CultureInfo.InvariantCulture);
}
