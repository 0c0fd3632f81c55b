using System.Runtime.InteropServices;

namespace RobotControl.Bus.Transports.Serial;

/// <summary>
/// What <c>statx(2)</c> says about a path (links followed): its type, and the device and inode that identify it
/// (as <c>/proc/locks</c> names a locked file).
/// </summary>
/// <param name="Mode">st_mode: file type and permission bits.</param>
/// <param name="DeviceMajor">Major number of the device holding the file.</param>
/// <param name="DeviceMinor">Minor number of the device holding the file.</param>
/// <param name="Inode">Inode number.</param>
public readonly record struct FileIdentity(int Mode, uint DeviceMajor, uint DeviceMinor, ulong Inode)
{
    private const int TypeMask = 0xF000, Regular = 0x8000, CharacterDevice = 0x2000;

    /// <summary>True for a regular file.</summary>
    public bool IsRegularFile => (Mode & TypeMask) == Regular;

    /// <summary>True for a character device (a tty, a pty, /dev/full).</summary>
    public bool IsCharacterDevice => (Mode & TypeMask) == CharacterDevice;

    /// <summary>The identity of <paramref name="path"/>; false when it does not exist, cannot be examined, or the system has no statx.</summary>
    public static bool TryGet(string path, out FileIdentity identity)
    {
        identity = default;
        if (!OperatingSystem.IsLinux())
        {
            return false;
        }

        try
        {
            if (Libc.Statx(path, out var mode, out var major, out var minor, out var inode) != 0)
            {
                return false;
            }

            identity = new FileIdentity(mode, major, minor, inode);
            return true;
        }
        catch (EntryPointNotFoundException)
        {
            return false;
        }
        catch (DllNotFoundException)
        {
            return false;
        }
    }
}
