using RobotControl.Bus.Transports.Serial;

namespace RobotControl.Cli.Output;

/// <summary>
/// Checks, before any work starts, that an output can be written where the user asked: the directory exists and
/// takes a new file (probed with a temporary file, which also catches read-only file systems and permissions), and
/// the target is not something a file cannot replace (a directory, a device such as <c>/dev/full</c>, a pipe).
/// Outputs are then written with <see cref="AtomicFile"/>, so a failure while writing leaves no half-written file.
/// </summary>
internal static class OutputPath
{
    /// <summary>The problem with writing a file at <paramref name="path"/> (full path), or null when it can be written.</summary>
    public static string? CheckFile(string path)
    {
        ArgumentException.ThrowIfNullOrEmpty(path);
        if (Directory.Exists(path))
        {
            return $"{path} is a directory; give a file name";
        }

        if (IsSpecial(path))
        {
            return $"{path} is not a regular file (a device, pipe or socket); give a file in a directory";
        }

        var directory = Path.GetDirectoryName(path);
        if (directory is null)
        {
            return $"{path} has no directory";
        }

        if (!Directory.Exists(directory))
        {
            return File.Exists(directory) ? $"{directory} is a file, not a directory" : $"directory {directory} does not exist";
        }

        return ProbeDirectory(directory);
    }

    /// <summary>
    /// The problem with writing into directory <paramref name="path"/> (full path; created if missing), or null. A
    /// missing directory's nearest existing ancestor must be a writable directory.
    /// </summary>
    public static string? CheckDirectory(string path)
    {
        ArgumentException.ThrowIfNullOrEmpty(path);
        if (File.Exists(path))
        {
            return $"{path} is a file, not a directory";
        }

        var existing = path;
        while (!Directory.Exists(existing))
        {
            if (File.Exists(existing))
            {
                return $"{existing} is a file, so directory {path} cannot be created";
            }

            existing = Path.GetDirectoryName(existing);
            if (existing is null)
            {
                return $"no part of {path} exists";
            }
        }

        return ProbeDirectory(existing);
    }

    // A device (e.g. /dev/full), pipe or socket cannot take a renamed file; a link to a regular file is followed.
    private static bool IsSpecial(string path) =>
        FileIdentity.TryGet(path, out var identity) && !identity.IsRegularFile;

    private static string? ProbeDirectory(string directory)
    {
        var probe = Path.Combine(directory, $".robotctl-probe-{Environment.ProcessId}-{Guid.NewGuid():N}");
        try
        {
            using (var stream = new FileStream(probe, FileMode.CreateNew, FileAccess.Write, FileShare.None, 1, FileOptions.DeleteOnClose))
            {
                stream.WriteByte(0);
                stream.Flush(flushToDisk: false);
            }

            return null;
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            return $"cannot write in {directory} ({ex.Message})";
        }
        finally
        {
            File.Delete(probe);
        }
    }
}
