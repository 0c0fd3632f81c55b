using System.Reflection;
using System.Runtime.Loader;

namespace RobotControl.Runtime.Discovery;

/// <summary>
/// One load context per plug-in assembly: the plug-in's own dependencies resolve from its folder (its .deps.json),
/// while assemblies the host already has (the SDK, the robot model, kinematics, the framework) are shared, so a
/// plug-in's <c>Plugin</c> is the host's <c>Plugin</c>.
/// </summary>
internal sealed class PluginLoadContext(string assemblyPath) : AssemblyLoadContext(Path.GetFileNameWithoutExtension(assemblyPath), isCollectible: false)
{
    private readonly AssemblyDependencyResolver _resolver = new(assemblyPath);

    protected override Assembly? Load(AssemblyName assemblyName)
    {
        // Share anything the host has loaded (or can load) by name: type identity across the boundary matters more
        // than version isolation for the SDK contracts.
        var shared = Default.Assemblies.FirstOrDefault(a => AssemblyName.ReferenceMatchesDefinition(assemblyName, a.GetName()));
        if (shared is not null)
        {
            return shared;
        }

        var path = _resolver.ResolveAssemblyToPath(assemblyName);
        return path is null ? null : LoadFromAssemblyPath(path);
    }

    protected override IntPtr LoadUnmanagedDll(string unmanagedDllName)
    {
        var path = _resolver.ResolveUnmanagedDllToPath(unmanagedDllName);
        return path is null ? IntPtr.Zero : LoadUnmanagedDllFromPath(path);
    }
}
