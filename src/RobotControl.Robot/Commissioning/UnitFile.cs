using System.Globalization;
using System.Text.Json;
using System.Text.Json.Serialization;
using RobotControl.Bus.Protocol;

namespace RobotControl.Robot.Commissioning;

/// <summary>
/// A commissioned unit, <c>hardware/units/&lt;name&gt;.json</c>: which robot file it was built to, and for every module
/// whose parameters were all written and verified, its ID, name, firmware version and those parameters. A module not
/// in it is not done (a resumed commissioning redoes it). Written atomically (a temporary file renamed over it).
/// </summary>
public sealed class UnitFile
{
    private static readonly JsonSerializerOptions Json = new() { WriteIndented = true, PropertyNamingPolicy = JsonNamingPolicy.SnakeCaseLower, DefaultIgnoreCondition = JsonIgnoreCondition.WhenWritingNull };

    /// <summary>The unit's name (the file's name without <c>.json</c>).</summary>
    public required string Unit { get; init; }

    /// <summary>The robot file it was commissioned from, as given.</summary>
    public required string RobotFile { get; init; }

    /// <summary>When the last module was recorded (UTC, ISO 8601).</summary>
    public string? Date { get; set; }

    /// <summary>The modules done, in the order they were commissioned.</summary>
    public List<UnitModule> Modules { get; init; } = [];

    /// <summary>The path of unit <paramref name="name"/> under <paramref name="directory"/>.</summary>
    /// <exception cref="ArgumentException">The name is empty or holds a path separator.</exception>
    public static string PathOf(string directory, string name)
    {
        if (string.IsNullOrWhiteSpace(name) || name.IndexOfAny(['/', '\\', Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar]) >= 0 || name is "." or "..")
        {
            throw new ArgumentException($"--unit '{name}': a unit name is a file name (no path separator); the file is {Path.Combine(directory, "<name>.json")}");
        }

        return Path.Combine(directory, name + ".json");
    }

    /// <summary>Reads <paramref name="path"/>; null when there is no such file.</summary>
    /// <exception cref="ArgumentException">The file is not a unit file (the message names it).</exception>
    public static UnitFile? Load(string path)
    {
        if (!File.Exists(path))
        {
            return null;
        }

        try
        {
            return JsonSerializer.Deserialize<UnitFile>(File.ReadAllText(path), Json) ?? throw new JsonException("empty");
        }
        catch (JsonException ex)
        {
            throw new ArgumentException($"{path}: not a unit file ({ex.Message})");
        }
    }

    /// <summary>Writes the file atomically: a reader sees the old one or the new one, never half of it.</summary>
    public void Save(string path, DateTimeOffset now)
    {
        Date = now.UtcDateTime.ToString("yyyy-MM-ddTHH:mm:ssZ", CultureInfo.InvariantCulture);
        Directory.CreateDirectory(Path.GetDirectoryName(Path.GetFullPath(path))!);
        var temporary = path + ".tmp";
        using (var stream = new FileStream(temporary, FileMode.Create, FileAccess.Write))
        {
            JsonSerializer.Serialize(stream, this, Json);
            stream.Flush(flushToDisk: true);
        }

        File.Move(temporary, path, overwrite: true);
    }

    /// <summary>The module recorded with robot-file ID <paramref name="id"/>, or null.</summary>
    public UnitModule? Module(byte id) => Modules.FirstOrDefault(m => m.Id == id);

    /// <summary>The key a parameter is recorded under: <c>kp[0]</c> for a per-motor field, <c>return_delay_time</c> for one per module.</summary>
    public static string Key(ControlTableField field, int motor) =>
        field.Count > 1 ? string.Create(CultureInfo.InvariantCulture, $"{field.Name}[{motor}]") : field.Name;

    /// <summary>The field and motor of a recorded <paramref name="key"/>.</summary>
    /// <exception cref="ArgumentException">The control table has no such field.</exception>
    public static (ControlTableField Field, int Motor) Parse(ControlTable table, string key)
    {
        var open = key.IndexOf('[', StringComparison.Ordinal);
        var name = open < 0 ? key : key[..open];
        var motor = open < 0 ? 0 : int.Parse(key[(open + 1)..^1], CultureInfo.InvariantCulture);
        return table.Contains(name) ? (table[name], motor) : throw new ArgumentException($"unit file parameter '{key}': the control table has no field '{name}'");
    }
}

/// <summary>One commissioned module of a <see cref="UnitFile"/>.</summary>
public sealed class UnitModule
{
    /// <summary>Its ID (the robot file's).</summary>
    public required byte Id { get; init; }

    /// <summary>Its name in the robot file.</summary>
    public required string Name { get; init; }

    /// <summary>The model number it reports.</summary>
    public required int ModelNumber { get; init; }

    /// <summary>The firmware version it reports.</summary>
    public required int FirmwareVersion { get; init; }

    /// <summary>Every parameter written and verified by read-back, by <see cref="UnitFile.Key"/>.</summary>
    public required SortedDictionary<string, long> Parameters { get; init; }

    /// <summary>Its motors' pot calibrations (<c>robotctl calibrate pots</c>), by the motor's <c>arm.joint</c>; null before any.</summary>
    public SortedDictionary<string, UnitPotCalibration>? PotCalibration { get; set; }
}

/// <summary>One motor's pot calibration in a <see cref="UnitFile"/>: its table is in the module's <see cref="UnitModule.Parameters"/> (<c>pot_cal_*</c>).</summary>
public sealed class UnitPotCalibration
{
    /// <summary>When it was written into the module (UTC, ISO 8601).</summary>
    public required string Date { get; init; }

    /// <summary>Pot readings the table was fitted to.</summary>
    public required int Samples { get; init; }

    /// <summary>The verification sweep's worst pot/encoder disagreement, degrees of output (null: not verified).</summary>
    public double? WorstDeg { get; set; }

    /// <summary>True once the verification sweep stayed within its bound.</summary>
    public bool Verified { get; set; }
}
