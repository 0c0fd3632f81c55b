using System.Reflection;

namespace RobotControl.Plugins.Sdk;

/// <summary>
/// The version of this SDK (semantic versioning). A plug-in assembly records the version it was compiled against in
/// its reference to <c>RobotControl.Plugins.Sdk</c>; the host loads plug-ins built for its own major version only.
/// </summary>
public static class SdkVersion
{
    /// <summary>The SDK assembly's version (major.minor.patch.0).</summary>
    public static Version Current { get; } = typeof(SdkVersion).Assembly.GetName().Version ?? new Version(0, 0);

    /// <summary>The SDK's semantic version as packaged, e.g. <c>1.0.0</c> or <c>1.1.0-preview.1</c>.</summary>
    public static string Text { get; } =
        typeof(SdkVersion).Assembly.GetCustomAttribute<AssemblyInformationalVersionAttribute>()?.InformationalVersion ?? Format(Current);

    /// <summary>major.minor.patch of <paramref name="version"/> (an assembly version's fourth part is always 0 here).</summary>
    public static string Format(Version version)
    {
        ArgumentNullException.ThrowIfNull(version);
        return $"{version.Major}.{version.Minor}.{Math.Max(version.Build, 0)}";
    }
}
