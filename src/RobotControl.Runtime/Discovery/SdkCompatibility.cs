using System.Reflection;
using RobotControl.Plugins.Sdk;

namespace RobotControl.Runtime.Discovery;

/// <summary>
/// Which SDK version a plug-in assembly was built against (the version in its reference to the SDK assembly, written by
/// the compiler) and whether this host can load it: same major version as the host's SDK.
/// </summary>
public static class SdkCompatibility
{
    /// <summary>The SDK assembly's simple name.</summary>
    public static string SdkAssemblyName { get; } = typeof(Plugin).Assembly.GetName().Name!;

    /// <summary>The SDK version <paramref name="assembly"/> was built against; the host's own for the SDK itself.</summary>
    public static Version BuiltAgainst(Assembly assembly)
    {
        ArgumentNullException.ThrowIfNull(assembly);
        if (assembly == typeof(Plugin).Assembly)
        {
            return SdkVersion.Current;
        }

        return assembly.GetReferencedAssemblies().FirstOrDefault(r => r.Name == SdkAssemblyName)?.Version ?? SdkVersion.Current;
    }

    /// <summary>
    /// Null when a plug-in built against <paramref name="builtAgainst"/> can run on a host with SDK
    /// <paramref name="host"/>; otherwise the one-line reason, naming the plug-in and both versions.
    /// </summary>
    public static string? Problem(string plugin, Version builtAgainst, Version host)
    {
        ArgumentException.ThrowIfNullOrEmpty(plugin);
        ArgumentNullException.ThrowIfNull(builtAgainst);
        ArgumentNullException.ThrowIfNull(host);
        return builtAgainst.Major == host.Major
            ? null
            : $"{plugin}: built against plug-in SDK {SdkVersion.Format(builtAgainst)}, this host has SDK {SdkVersion.Format(host)} (major versions differ); not loaded, rebuild it against SDK {host.Major}.x";
    }
}
