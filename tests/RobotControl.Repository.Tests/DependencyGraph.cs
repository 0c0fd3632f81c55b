using System.Text;
using System.Xml.Linq;
using RobotControl.TestSupport;

namespace RobotControl.Repository.Tests;

/// <summary>
/// The Mermaid picture of the production projects' references (every <c>.csproj</c> under <c>src/</c> and
/// <c>plugins/</c>), generated from the project files. docs/architecture.md holds it between two marker comments.
/// </summary>
internal static class DependencyGraph
{
    public const string Begin = "<!-- dependency graph: generated from the .csproj files by tools/deps-graph.sh; do not edit by hand -->";
    public const string End = "<!-- end of dependency graph -->";

    private const string Prefix = "RobotControl.";

    /// <summary>The Markdown block (markers included) for the project files as they are now.</summary>
    public static string Generate()
    {
        var projects = ProductionProjectFiles().ToDictionary(p => Path.GetFileNameWithoutExtension(p), References, StringComparer.Ordinal);

        var text = new StringBuilder();
        text.Append(Begin).Append('\n');
        text.Append("```mermaid\n");
        text.Append("graph BT\n");
        foreach (var name in projects.Keys.Order(StringComparer.Ordinal))
        {
            text.Append("  ").Append(Id(name)).Append("[\"").Append(name).Append("\"]\n");
        }

        foreach (var (name, references) in projects.OrderBy(p => p.Key, StringComparer.Ordinal))
        {
            foreach (var reference in references.Where(projects.ContainsKey).Order(StringComparer.Ordinal))
            {
                text.Append("  ").Append(Id(name)).Append(" --> ").Append(Id(reference)).Append('\n');
            }
        }

        text.Append("```\n");
        text.Append(End);
        return text.ToString();
    }

    /// <summary>The full paths of the production projects: every <c>.csproj</c> under <c>src/</c> and <c>plugins/</c>.</summary>
    public static IEnumerable<string> ProductionProjectFiles() =>
        new[] { "src", "plugins" }
            .SelectMany(folder => Directory.EnumerateFiles(RepositoryPaths.Of(folder), "*.csproj", SearchOption.AllDirectories))
            .Where(p => !p.Contains($"{Path.DirectorySeparatorChar}obj{Path.DirectorySeparatorChar}", StringComparison.Ordinal));

    /// <summary>The block currently in <paramref name="document"/>, or null when the markers are missing.</summary>
    public static string? Current(string document)
    {
        var begin = document.IndexOf(Begin, StringComparison.Ordinal);
        var end = document.IndexOf(End, StringComparison.Ordinal);
        return begin < 0 || end < begin ? null : document[begin..(end + End.Length)];
    }

    private static List<string> References(string projectFile) =>
        XDocument.Load(projectFile).Descendants("ProjectReference")
            .Select(r => Path.GetFileNameWithoutExtension(((string?)r.Attribute("Include") ?? "").Replace('\\', '/')))
            .Where(n => n.Length > 0)
            .ToList();

    private static string Id(string project) =>
        (project.StartsWith(Prefix, StringComparison.Ordinal) ? project[Prefix.Length..] : project).Replace('.', '_');
}
