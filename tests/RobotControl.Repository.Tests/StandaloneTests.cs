using RobotControl.TestSupport;

namespace RobotControl.Repository.Tests;

/// <summary>The repository stands alone: nothing points outside it, and every path a document or comment names exists.</summary>
public sealed class StandaloneTests
{
    // Written in two parts so that this file does not name what it forbids.
    private static readonly string[] OutsideMarkers = ["shared" + "/spec", "../" + "shared/", "/" + "work/"];

    [Fact]
    public void No_tracked_text_file_refers_outside_the_repository()
    {
        var found = TrackedFiles.Text()
            .SelectMany(f => f.Text.Split('\n').Select((line, i) => (f.Path, Line: i + 1, Text: line)))
            .Where(l => OutsideMarkers.Any(m => l.Text.Contains(m, StringComparison.Ordinal)))
            .Select(l => $"{l.Path}:{l.Line}: {l.Text.Trim()}")
            .ToList();

        Assert.True(found.Count == 0, "references outside the repository:\n" + string.Join('\n', found));
    }

    [Fact]
    public void Every_path_a_document_or_code_comment_names_exists_inside_the_repository()
    {
        var root = RepositoryPaths.Root.TrimEnd(Path.DirectorySeparatorChar) + Path.DirectorySeparatorChar;
        // A template's content describes the project it generates: its paths are relative to that project, not to this
        // repository.
        var references = TrackedFiles.Text()
            .Where(f => !(f.Path.StartsWith("templates/", StringComparison.Ordinal) && f.Path.Contains("/content/", StringComparison.Ordinal)))
            .SelectMany(f => f.Path.EndsWith(".md", StringComparison.Ordinal) ? PathReferences.InMarkdown(f.Path, f.Text)
                : PathReferences.IsCode(f.Path) ? PathReferences.InCodeComments(f.Path, f.Text)
                : [])
            .ToList();

        var bad = references
            .Where(r => !(r.FullPath + Path.DirectorySeparatorChar).StartsWith(root, StringComparison.Ordinal)
                || !(File.Exists(r.FullPath) || Directory.Exists(r.FullPath)))
            .Select(r => $"{r.File}:{r.Line}: {r.Written}")
            .ToList();

        Assert.True(references.Count > 100, $"only {references.Count} path references found: the scan is broken");
        Assert.True(bad.Count == 0, "paths that do not exist in the repository:\n" + string.Join('\n', bad));
    }
}
