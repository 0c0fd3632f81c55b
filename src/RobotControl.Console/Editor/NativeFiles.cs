using System.Runtime.InteropServices;

namespace RobotControl.WebConsole.Editor;

/// <summary>
/// What .NET does not say about a path on Linux: its real path (every symbolic link and <c>..</c> resolved, libc's
/// <c>realpath</c>) and its file type without opening it (<c>statx</c>, whose layout is the same on every Linux
/// architecture). Opening a FIFO to find out what it is would block until a writer comes.
/// </summary>
internal static partial class NativeFiles
{
    private const int AtFdCwd = -100;
    private const int AtSymlinkNoFollow = 0x100;
    private const uint StatxType = 0x1;
    private const int StatxModeOffset = 28;
    private const int TypeMask = 0xF000;

    /// <summary>The kinds of file the editor tells apart.</summary>
    public enum Kind
    {
        /// <summary>No such path (or it cannot be examined).</summary>
        Missing,

        /// <summary>A regular file.</summary>
        Regular,

        /// <summary>A directory.</summary>
        Directory,

        /// <summary>A symbolic link (the path's last part).</summary>
        Link,

        /// <summary>A FIFO, socket or device.</summary>
        Special,
    }

    /// <summary>The real path of an existing <paramref name="path"/>, or null when it does not exist.</summary>
    public static string? RealPath(string path)
    {
        if (!OperatingSystem.IsLinux())
        {
            return File.Exists(path) || Directory.Exists(path) ? Path.GetFullPath(path) : null;
        }

        var resolved = Realpath(path, 0);
        if (resolved == 0)
        {
            return null;
        }

        try
        {
            return Marshal.PtrToStringUTF8(resolved);
        }
        finally
        {
            Free(resolved);
        }
    }

    /// <summary>What <paramref name="path"/> is, not following a link at its end and opening nothing.</summary>
    public static Kind KindOf(string path)
    {
        if (!OperatingSystem.IsLinux())
        {
            return Directory.Exists(path) ? Kind.Directory : File.Exists(path) ? Kind.Regular : Kind.Missing;
        }

        var buffer = new byte[256];
        if (Statx(AtFdCwd, path, AtSymlinkNoFollow, StatxType, buffer) != 0)
        {
            return Kind.Missing;
        }

        return (BitConverter.ToUInt16(buffer, StatxModeOffset) & TypeMask) switch
        {
            0x8000 => Kind.Regular,
            0x4000 => Kind.Directory,
            0xA000 => Kind.Link,
            _ => Kind.Special,
        };
    }

    [LibraryImport("libc", EntryPoint = "realpath", StringMarshalling = StringMarshalling.Utf8)]
    private static partial nint Realpath(string path, nint resolved);

    [LibraryImport("libc", EntryPoint = "free")]
    private static partial void Free(nint pointer);

    [LibraryImport("libc", EntryPoint = "statx", StringMarshalling = StringMarshalling.Utf8)]
    private static partial int Statx(int directory, string path, int flags, uint mask, [Out] byte[] buffer);
}
