using System.Globalization;
using System.Text.Json;
using RobotControl.TestSupport;

namespace RobotControl.Repository.Tests;

/// <summary>
/// The control table in docs/protocol.md ("## Control table") is the one of firmware/protocol/control-table.json,
/// row for row (issue 29: the doc once said firmware_version 1 while the modules said 2).
/// </summary>
public sealed class ProtocolTableDocTests
{
    [Fact]
    public void The_control_table_in_the_protocol_doc_is_generated_from_the_control_table_json()
    {
        var expected = Rows();
        var current = DocumentRows();

        var first = expected.Zip(current).FirstOrDefault(p => p.First != p.Second);
        Assert.True(
            expected.Count == current.Count && first == default,
            first == default
                ? $"docs/protocol.md's control table has {current.Count} rows, control-table.json {expected.Count} fields; the table should be:\n{string.Join('\n', expected)}"
                : $"docs/protocol.md's control table differs from control-table.json:\n  doc:  {first.Second}\n  json: {first.First}");
    }

    [Fact]
    public void The_firmware_version_row_gives_the_version_the_modules_report()
    {
        using var doc = JsonDocument.Parse(File.ReadAllText(RepositoryPaths.Firmware("protocol/control-table.json")));
        var version = doc.RootElement.GetProperty("fields").EnumerateArray().Single(f => f.GetProperty("name").GetString() == "firmware_version").GetProperty("default").GetInt32();
        var row = DocumentRows().Single(r => r.StartsWith("| 6 | firmware_version |", StringComparison.Ordinal));

        Assert.Equal(version.ToString(CultureInfo.InvariantCulture), row.Split(" | ")[8]);
    }

    /// <summary>The table's rows as control-table.json gives them ('|' in a description shown as '/').</summary>
    private static List<string> Rows()
    {
        using var doc = JsonDocument.Parse(File.ReadAllText(RepositoryPaths.Firmware("protocol/control-table.json")));
        var rows = new List<string>();
        foreach (var f in doc.RootElement.GetProperty("fields").EnumerateArray())
        {
            var (address, count, stride) = (f.GetProperty("address").GetInt32(), f.GetProperty("count").GetInt32(), f.GetProperty("stride").GetInt32());
            var addresses = string.Join(", ", Enumerable.Range(0, count).Select(k => (address + (k * stride)).ToString(CultureInfo.InvariantCulture)));
            var instances = count == 1 ? "1" : string.Create(CultureInfo.InvariantCulture, $"{count} x {stride}");
            rows.Add(string.Create(
                CultureInfo.InvariantCulture,
                $"| {addresses} | {Text(f, "name")} | {Text(f, "type")} | {f.GetProperty("size").GetInt32()} | {instances} | {Text(f, "access")} | {Text(f, "area")} | {Text(f, "unit")} | {Number(f, "default")} | {Number(f, "min")}..{Number(f, "max")} | {Text(f, "description").Replace('|', '/')} |"));
        }

        return rows;
    }

    /// <summary>The rows of the table under "## Control table" in docs/protocol.md.</summary>
    private static List<string> DocumentRows()
    {
        var lines = File.ReadAllLines(RepositoryPaths.Of("docs/protocol.md"));
        var section = Array.IndexOf(lines, "## Control table");
        Assert.True(section >= 0, "docs/protocol.md has no '## Control table' section");
        return lines.Skip(section + 1)
            .SkipWhile(l => !l.StartsWith("| address |", StringComparison.Ordinal))
            .Skip(2) // the header and its rule
            .TakeWhile(l => l.StartsWith("| ", StringComparison.Ordinal))
            .ToList();
    }

    private static string Text(JsonElement field, string name) => field.GetProperty(name).GetString() ?? string.Empty;

    private static string Number(JsonElement field, string name) => field.GetProperty(name).GetInt64().ToString(CultureInfo.InvariantCulture);
}
