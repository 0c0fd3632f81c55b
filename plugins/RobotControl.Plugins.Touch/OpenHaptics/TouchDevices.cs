namespace RobotControl.Plugins.Touch.OpenHaptics;

/// <summary>What <see cref="TouchDevices.Probe"/> found for one device name.</summary>
/// <param name="Name">The name tried (empty: the default device).</param>
/// <param name="Info">The device, when it opened.</param>
/// <param name="Error">Why it did not open (the device's error text), when it did not.</param>
public sealed record TouchProbe(string Name, HdDeviceInfo? Info, string? Error);

/// <summary>Lists the Touch devices the HD library can open (for <c>robotctl devices</c>).</summary>
public static class TouchDevices
{
    /// <summary>
    /// Loads the library (<paramref name="libraryPath"/> or the search path) and tries to open each of
    /// <paramref name="names"/> (empty name: the default device), reading identity, calibration and nominal forces,
    /// then closes it. Do not call while Touch plug-ins run in the same process.
    /// </summary>
    /// <exception cref="TouchDeviceException">The library is not installed (one line naming what to install).</exception>
    public static IReadOnlyList<TouchProbe> Probe(string libraryPath, IEnumerable<string> names)
    {
        ArgumentNullException.ThrowIfNull(libraryPath);
        ArgumentNullException.ThrowIfNull(names);
        HdLibrary.Load(libraryPath);
        var found = new List<TouchProbe>();
        foreach (var name in names)
        {
            var handle = HdNative.hdInitDevice(name.Length == 0 ? null : name);
            if (handle == HdConstants.InvalidHandle)
            {
                found.Add(new TouchProbe(name, null, HdNative.TakeError() ?? "cannot be opened"));
                continue;
            }

            HdNative.hdMakeCurrentDevice(handle);
            var info = HdDeviceInfo.ReadCurrent(name);
            var error = HdNative.TakeError();
            HdNative.hdDisableDevice(handle);
            HdNative.hdGetError();
            found.Add(error is null ? new TouchProbe(name, info, null) : new TouchProbe(name, null, error));
        }

        return found;
    }
}
