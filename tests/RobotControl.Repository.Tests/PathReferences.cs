using System.Buffers;
using System.Text.RegularExpressions;
using RobotControl.TestSupport;

namespace RobotControl.Repository.Tests;

/// <summary>
/// Finds the repository paths a document or a code comment names. The rule, kept small on purpose:
/// <list type="bullet">
/// <item>In Markdown, a link target that is not a URL or a bare anchor names a path relative to the document's folder.</item>
/// <item>In Markdown, a word inside backquotes, and in a code comment any word, names a path from the repository root
/// when its first segment is a tracked top-level entry (<c>src</c>, <c>docs</c>, <c>README.md</c>, ...) and it has a
/// '/' or a file extension.</item>
/// <item>A word holding a placeholder or wildcard (<c>&lt; &gt; { } * $ …</c>) names a pattern, not a path, and a word with
/// a <c>bin</c> or <c>obj</c> folder names a build output; both are skipped.</item>
/// </list>
/// </summary>
internal static partial class PathReferences
{
    private static readonly SearchValues<char> PatternChars = SearchValues.Create("<>{}*$…|?%=");

    /// <summary>One named path: the file naming it, the line, the text as written and the full path it resolves to.</summary>
    public sealed record Reference(string File, int Line, string Written, string FullPath);

    /// <summary>Markdown files: every link target and every backquoted root-relative path.</summary>
    public static IEnumerable<Reference> InMarkdown(string file, string text)
    {
        var folder = Path.GetDirectoryName(RepositoryPaths.Of(file))!;
        var lines = text.Split('\n');
        for (var i = 0; i < lines.Length; i++)
        {
            foreach (Match m in MarkdownLink().Matches(lines[i]))
            {
                var target = m.Groups[1].Value;
                if (target.StartsWith('#') || UrlScheme().IsMatch(target))
                {
                    continue;
                }

                var withoutAnchor = target.Split('#')[0];
                yield return new Reference(file, i + 1, target, Path.GetFullPath(Path.Combine(folder, withoutAnchor)));
            }

            foreach (Match m in Backquoted().Matches(lines[i]))
            {
                foreach (var word in Words(m.Groups[1].Value))
                {
                    if (RootRelative(word) is { } full)
                    {
                        yield return new Reference(file, i + 1, word, full);
                    }
                }
            }
        }
    }

    /// <summary>Code files: root-relative paths in comments (<c>//</c>, <c>/* */</c> lines starting with <c>*</c>, or <c>#</c> for scripts).</summary>
    public static IEnumerable<Reference> InCodeComments(string file, string text)
    {
        var hashComments = file.EndsWith(".sh", StringComparison.Ordinal) || file.EndsWith(".py", StringComparison.Ordinal)
            || file.EndsWith("CMakeLists.txt", StringComparison.Ordinal) || file.EndsWith(".cmake", StringComparison.Ordinal);
        var lines = text.Split('\n');
        for (var i = 0; i < lines.Length; i++)
        {
            var comment = CommentOf(lines[i], hashComments);
            if (comment is null)
            {
                continue;
            }

            foreach (var word in Words(comment))
            {
                if (RootRelative(word) is { } full)
                {
                    yield return new Reference(file, i + 1, word, full);
                }
            }
        }
    }

    /// <summary>True for the code files whose comments are checked.</summary>
    public static bool IsCode(string file) =>
        new[] { ".cs", ".c", ".h", ".cpp", ".sh", ".py", ".cmake", "CMakeLists.txt" }.Any(e => file.EndsWith(e, StringComparison.Ordinal));

    private static string? CommentOf(string line, bool hash)
    {
        if (hash)
        {
            var h = line.IndexOf('#', StringComparison.Ordinal);
            return h >= 0 ? line[(h + 1)..] : null;
        }

        var slash = line.IndexOf("//", StringComparison.Ordinal);
        if (slash >= 0)
        {
            return line[(slash + 2)..];
        }

        var trimmed = line.TrimStart();
        return trimmed.StartsWith('*') || trimmed.StartsWith("/*", StringComparison.Ordinal) ? trimmed : null;
    }

    private static IEnumerable<string> Words(string text) =>
        WordSplit().Split(text).Select(w => w.TrimEnd('.', ':', ',').TrimStart('.')).Where(w => w.Length > 0);

    private static string? RootRelative(string word)
    {
        if (word.AsSpan().IndexOfAny(PatternChars) >= 0 || word.Contains("...", StringComparison.Ordinal))
        {
            return null;
        }

        var segments = word.Split('/');
        if (segments.Contains("bin") || segments.Contains("obj"))
        {
            return null;
        }

        var first = segments[0];
        var hasExtension = Path.HasExtension(word) && !word.EndsWith('/');
        if (!TrackedFiles.TopLevelEntries.Contains(first) || (!word.Contains('/', StringComparison.Ordinal) && !hasExtension))
        {
            return null;
        }

        return Path.GetFullPath(RepositoryPaths.Of(word.TrimEnd('/')));
    }

    [GeneratedRegex(@"\]\(([^)\s]+)\)")]
    private static partial Regex MarkdownLink();

    [GeneratedRegex("`([^`]+)`")]
    private static partial Regex Backquoted();

    [GeneratedRegex(@"^[a-zA-Z][a-zA-Z0-9+.-]*:")]
    private static partial Regex UrlScheme();

    [GeneratedRegex(@"[\s`'""()\[\],;]+")]
    private static partial Regex WordSplit();
}
