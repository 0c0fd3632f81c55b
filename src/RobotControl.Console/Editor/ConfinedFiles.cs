namespace RobotControl.WebConsole.Editor;

/// <summary>
/// The files the editor may read, and so the only ones a graph checked, saved or started from the pages may name: those
/// whose real path (every symbolic link and <c>..</c> resolved) is inside the graphs folder or the robot folder (the
/// folder of the robot file the console's graph names), and that are regular files (a FIFO, socket or device is never
/// opened: a FIFO would hold the request until a writer came). A refusal names the field and the path as given, never
/// anything read from a file. Reads are bounded to <see cref="MaxBytes"/>.
/// </summary>
public sealed class ConfinedFiles
{
    /// <summary>The largest file the editor reads.</summary>
    public const long MaxBytes = 4 * 1024 * 1024;

    private readonly string[] _roots;

    /// <summary>Confines reads to <paramref name="folders"/> (existing ones; their real paths).</summary>
    public ConfinedFiles(params string?[] folders)
    {
        _roots = [.. folders.OfType<string>().Select(NativeFiles.RealPath).OfType<string>().Distinct(StringComparer.Ordinal)];
    }

    /// <summary>The folders' real paths.</summary>
    public IReadOnlyList<string> Roots => _roots;

    /// <summary>
    /// Why <paramref name="path"/> (given as <paramref name="given"/> in <paramref name="field"/>) may not be read, or
    /// null when it may: inside the folders and a regular file, or a directory when <paramref name="folderToo"/>. A path
    /// that does not exist yet is judged by the real path of its nearest existing parent.
    /// </summary>
    public string? Problem(string field, string given, string path, bool folderToo = false)
    {
        var full = Path.GetFullPath(path);
        var real = RealOrParent(full);
        if (real is null || !_roots.Any(root => Inside(real, root)))
        {
            return $"{field}: '{given}' is outside the graphs folder and the robot folder (links that leave them are not followed)";
        }

        return NativeFiles.KindOf(real) switch
        {
            NativeFiles.Kind.Missing or NativeFiles.Kind.Regular => null,
            NativeFiles.Kind.Directory when folderToo => null,
            NativeFiles.Kind.Directory => $"{field}: '{given}' is a folder, not a file",
            _ => $"{field}: '{given}' is not a regular file (a FIFO, socket or device is never opened)",
        };
    }

    /// <summary>The text of <paramref name="path"/> after <see cref="Problem"/>, or null with the refusal (content never quoted).</summary>
    public string? ReadText(string field, string given, string path, out string refusal)
    {
        refusal = Problem(field, given, path) ?? string.Empty;
        if (refusal.Length > 0)
        {
            return null;
        }

        if (NativeFiles.KindOf(NativeFiles.RealPath(path) ?? path) != NativeFiles.Kind.Regular)
        {
            refusal = $"{field}: '{given}': no such file";
            return null;
        }

        try
        {
            using var stream = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.ReadWrite, 4096, FileOptions.SequentialScan);
            if (stream.Length > MaxBytes)
            {
                refusal = $"{field}: '{given}' is larger than {MaxBytes / (1024 * 1024)} MiB";
                return null;
            }

            using var reader = new StreamReader(stream);
            var buffer = new char[MaxBytes + 1];
            var count = reader.ReadBlock(buffer, 0, buffer.Length);
            if (count > MaxBytes)
            {
                refusal = $"{field}: '{given}' is larger than {MaxBytes / (1024 * 1024)} MiB";
                return null;
            }

            return new string(buffer, 0, count);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            refusal = $"{field}: '{given}' cannot be read ({ex.GetType().Name})";
            return null;
        }
    }

    private static bool Inside(string real, string root) =>
        real == root || real.StartsWith(root.EndsWith(Path.DirectorySeparatorChar) ? root : root + Path.DirectorySeparatorChar, StringComparison.Ordinal);

    /// <summary>The real path of <paramref name="full"/>, or of its nearest existing parent with the rest appended.</summary>
    private static string? RealOrParent(string full)
    {
        var rest = new Stack<string>();
        var current = full;
        while (true)
        {
            if (NativeFiles.RealPath(current) is { } real)
            {
                return rest.Aggregate(real, Path.Combine);
            }

            var parent = Path.GetDirectoryName(current);
            if (parent is null)
            {
                return null;
            }

            rest.Push(Path.GetFileName(current));
            current = parent;
        }
    }
}
