using System.Reflection;

namespace RobotControl.Runtime.Discovery;

/// <summary>
/// The plug-in types available to graphs, by name: found by reflection in the host's assemblies and in plug-in
/// assemblies loaded from a folder (each in its own load context). Names must be unique.
/// </summary>
public sealed class PluginCatalog
{
    private readonly Dictionary<string, PluginTypeInfo> _types = new(StringComparer.Ordinal);
    private readonly List<string> _problems = [];

    /// <summary>Every type, by name.</summary>
    public IReadOnlyCollection<PluginTypeInfo> Types => _types.Values;

    /// <summary>How the plug-ins created from this catalogue open devices (set by the host; see <see cref="RobotControl.Plugins.Sdk.PluginContext.DeviceOpener"/>).</summary>
    public Func<string, RobotControl.Plugins.Sdk.Devices.IByteSource>? DeviceOpener { get; set; }

    /// <summary>Problems met while scanning (malformed plug-in types, duplicate names, unloadable assemblies).</summary>
    public IReadOnlyList<string> Problems => _problems;

    /// <summary>A catalogue of the plug-in types in <paramref name="assemblies"/>.</summary>
    public static PluginCatalog FromAssemblies(params Assembly[] assemblies)
    {
        ArgumentNullException.ThrowIfNull(assemblies);
        var catalog = new PluginCatalog();
        foreach (var assembly in assemblies)
        {
            catalog.AddAssembly(assembly);
        }

        return catalog;
    }

    /// <summary>The type named <paramref name="name"/>, or null.</summary>
    public PluginTypeInfo? Find(string name) => _types.GetValueOrDefault(name);

    /// <summary>Adds every plug-in type of <paramref name="assembly"/>.</summary>
    public void AddAssembly(Assembly assembly)
    {
        ArgumentNullException.ThrowIfNull(assembly);
        Type[] types;
        try
        {
            types = assembly.GetTypes();
        }
        catch (ReflectionTypeLoadException ex)
        {
            _problems.Add($"{assembly.GetName().Name}: some types could not be loaded ({ex.LoaderExceptions.FirstOrDefault()?.Message})");
            types = [.. ex.Types.OfType<Type>()];
        }

        foreach (var type in types.OrderBy(t => t.FullName, StringComparer.Ordinal))
        {
            var info = PluginTypeInfo.TryCreate(type, out var problem);
            if (problem is not null)
            {
                _problems.Add(problem);
            }

            if (info is null)
            {
                continue;
            }

            if (_types.TryGetValue(info.Name, out var existing))
            {
                if (existing.Type != info.Type)
                {
                    _problems.Add($"plug-in type name '{info.Name}' is used by {existing.Type.FullName} ({existing.AssemblyLocation}) and {info.Type.FullName} ({info.AssemblyLocation}); keeping the first");
                }

                continue;
            }

            _types.Add(info.Name, info);
        }
    }

    /// <summary>
    /// Loads every <c>*.dll</c> directly in <paramref name="folder"/> and in its immediate subfolders (one plug-in per
    /// subfolder, with its dependencies) that references the plug-in SDK, each into its own load context. An assembly
    /// built against another major version of the SDK is not loaded (one problem line naming it and both versions).
    /// </summary>
    public void AddFolder(string folder)
    {
        ArgumentException.ThrowIfNullOrEmpty(folder);
        if (!Directory.Exists(folder))
        {
            _problems.Add($"plug-ins folder '{folder}' does not exist");
            return;
        }

        var candidates = Directory.EnumerateFiles(folder, "*.dll")
            .Concat(Directory.EnumerateDirectories(folder).SelectMany(d => Directory.EnumerateFiles(d, Path.GetFileName(d) + ".dll")))
            .Order(StringComparer.Ordinal);
        foreach (var path in candidates)
        {
            try
            {
                // Peek at the references without loading into the host: only SDK users become plug-ins.
                Version? builtAgainst;
                using (var peek = new MetadataLoadProbe(path))
                {
                    builtAgainst = peek.ReferencedVersion(SdkCompatibility.SdkAssemblyName);
                }

                if (builtAgainst is null || IsHostAssembly(path))
                {
                    continue;
                }

                if (SdkCompatibility.Problem($"{Path.GetFileNameWithoutExtension(path)} ({path})", builtAgainst, Plugins.Sdk.SdkVersion.Current) is { } incompatible)
                {
                    _problems.Add(incompatible);
                    continue;
                }

                var context = new PluginLoadContext(Path.GetFullPath(path));
                AddAssembly(context.LoadFromAssemblyPath(Path.GetFullPath(path)));
            }
            catch (Exception ex) when (ex is IOException or BadImageFormatException or FileLoadException or UnauthorizedAccessException)
            {
                _problems.Add($"{path}: {ex.Message}");
            }
        }
    }

    private static bool IsHostAssembly(string path)
    {
        var name = AssemblyName.GetAssemblyName(path).Name;
        return name == SdkCompatibility.SdkAssemblyName;
    }
}
