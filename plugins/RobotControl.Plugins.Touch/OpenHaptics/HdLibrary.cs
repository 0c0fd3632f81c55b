using System.Reflection;
using System.Runtime.InteropServices;

namespace RobotControl.Plugins.Touch.OpenHaptics;

/// <summary>
/// Finds and loads the OpenHaptics HD library (libHD.so on Linux, HD.dll on Windows) for the P/Invokes of
/// <see cref="HdNative"/> through a DllImport resolver. Looks in the <c>library_path</c> setting when given (a file or
/// a folder; nothing else then), otherwise in each folder of LD_LIBRARY_PATH (PATH on Windows) and then the system's
/// library search. One library per process: the first load wins, and a later, different library_path is an error.
/// </summary>
public static class HdLibrary
{
    private static readonly Lock Gate = new();
    private static nint _handle;
    private static string? _loadedFrom;
    private static bool _resolverSet;

    /// <summary>The library's file name on this platform.</summary>
    public static string FileName =>
        OperatingSystem.IsWindows() ? "HD.dll" : OperatingSystem.IsMacOS() ? "libHD.dylib" : "libHD.so";

    /// <summary>Where the library was loaded from (null before it is).</summary>
    public static string? LoadedFrom
    {
        get
        {
            lock (Gate)
            {
                return _loadedFrom;
            }
        }
    }

    /// <summary>The places tried, in order, for a <paramref name="libraryPath"/> setting and a search path variable.</summary>
    public static IReadOnlyList<string> Candidates(string libraryPath, string? searchPath)
    {
        ArgumentNullException.ThrowIfNull(libraryPath);
        if (libraryPath.Length > 0)
        {
            return [Directory.Exists(libraryPath) ? Path.Combine(libraryPath, FileName) : libraryPath];
        }

        var candidates = new List<string>();
        foreach (var folder in (searchPath ?? "").Split(Path.PathSeparator, StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))
        {
            candidates.Add(Path.Combine(folder, FileName));
        }

        candidates.Add(FileName); // the system's search (ld.so.cache, /usr/lib, ...)
        return candidates;
    }

    /// <summary>Loads the library (once per process) from <paramref name="libraryPath"/> or the search path.</summary>
    /// <exception cref="TouchDeviceException">Not found (one line naming what to install), or a different library is already loaded.</exception>
    public static void Load(string libraryPath)
    {
        ArgumentNullException.ThrowIfNull(libraryPath);
        lock (Gate)
        {
            var candidates = Candidates(libraryPath, Environment.GetEnvironmentVariable(OperatingSystem.IsWindows() ? "PATH" : "LD_LIBRARY_PATH"));
            if (_handle != 0)
            {
                if (libraryPath.Length > 0 && !string.Equals(Path.GetFullPath(candidates[0]), _loadedFrom, StringComparison.Ordinal))
                {
                    throw new TouchDeviceException($"library_path '{libraryPath}': the OpenHaptics library is already loaded from {_loadedFrom} (one per process)");
                }

                return;
            }

            foreach (var candidate in candidates)
            {
                var rooted = Path.IsPathRooted(candidate) || candidate.Contains(Path.DirectorySeparatorChar, StringComparison.Ordinal);
                if ((!rooted || File.Exists(candidate)) && NativeLibrary.TryLoad(candidate, out var handle))
                {
                    _handle = handle;
                    _loadedFrom = rooted ? Path.GetFullPath(candidate) : candidate;
                    if (!_resolverSet)
                    {
                        NativeLibrary.SetDllImportResolver(typeof(HdLibrary).Assembly, Resolve);
                        _resolverSet = true;
                    }

                    return;
                }
            }

            throw new TouchDeviceException(
                $"OpenHaptics library {FileName} not found (tried {string.Join(", ", candidates)}): install OpenHaptics for Linux (3.4 or later) and the Geomagic Touch device driver, or set the Touch's library_path or LD_LIBRARY_PATH");
        }
    }

    private static nint Resolve(string name, Assembly assembly, DllImportSearchPath? searchPath)
    {
        if (!string.Equals(name, HdNative.Library, StringComparison.Ordinal))
        {
            return 0;
        }

        lock (Gate)
        {
            return _handle;
        }
    }
}
