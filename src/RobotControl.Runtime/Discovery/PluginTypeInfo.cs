using System.Reflection;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Runtime.Discovery;

/// <summary>A discovered plug-in type: its graph-file name, settings schema and how to create instances.</summary>
public sealed class PluginTypeInfo
{
    private readonly ConstructorInfo _constructor;
    private readonly bool _takesSettings;

    private PluginTypeInfo(string name, string description, Type type, SettingsSchema? settings, ConstructorInfo constructor, bool takesSettings)
    {
        Name = name;
        Description = description;
        Type = type;
        Settings = settings;
        _constructor = constructor;
        _takesSettings = takesSettings;
    }

    /// <summary>The name graph files use.</summary>
    public string Name { get; }

    /// <summary>One-line description.</summary>
    public string Description { get; }

    /// <summary>The plug-in class.</summary>
    public Type Type { get; }

    /// <summary>The settings schema, or null for a plug-in without settings.</summary>
    public SettingsSchema? Settings { get; }

    /// <summary>Where the type was loaded from.</summary>
    public string AssemblyLocation => Type.Assembly.Location;

    /// <summary>The plug-in assembly's name and version.</summary>
    public AssemblyName AssemblyName => Type.Assembly.GetName();

    /// <summary>The SDK version the plug-in's assembly was built against.</summary>
    public Version SdkVersion => SdkCompatibility.BuiltAgainst(Type.Assembly);

    /// <summary>Creates an instance (settings are validated by the plug-in's base constructor).</summary>
    /// <exception cref="SettingsException">The settings are invalid.</exception>
    public Plugin Create(PluginSettings? settings, PluginContext context)
    {
        ArgumentNullException.ThrowIfNull(context);
        object?[] arguments = _takesSettings ? [settings ?? Settings!.CreateDefault(), context] : [context];
        try
        {
            return (Plugin)_constructor.Invoke(arguments);
        }
        catch (TargetInvocationException ex) when (ex.InnerException is not null)
        {
            System.Runtime.ExceptionServices.ExceptionDispatchInfo.Capture(ex.InnerException).Throw();
            throw;
        }
    }

    /// <summary>Describes <paramref name="type"/>, or returns why it is not a usable plug-in type.</summary>
    internal static PluginTypeInfo? TryCreate(Type type, out string? problem)
    {
        problem = null;
        if (type.GetCustomAttribute<PluginTypeAttribute>() is not { } attribute)
        {
            return null;
        }

        if (!typeof(Plugin).IsAssignableFrom(type) || type.IsAbstract)
        {
            problem = $"{type.FullName}: [PluginType] on a type that is not a concrete Plugin";
            return null;
        }

        var settingsType = SettingsTypeOf(type);
        var parameters = settingsType is null ? new[] { typeof(PluginContext) } : [settingsType, typeof(PluginContext)];
        var constructor = type.GetConstructor(parameters);
        if (constructor is null)
        {
            problem = $"{type.FullName}: needs a public constructor ({string.Join(", ", parameters.Select(p => p.Name))})";
            return null;
        }

        return new PluginTypeInfo(attribute.Name, attribute.Description, type, settingsType is null ? null : SettingsSchema.For(settingsType), constructor, settingsType is not null);
    }

    private static Type? SettingsTypeOf(Type type)
    {
        for (var t = type; t is not null; t = t.BaseType)
        {
            if (t.IsGenericType && t.GetGenericTypeDefinition() == typeof(Plugin<>))
            {
                return t.GetGenericArguments()[0];
            }
        }

        return null;
    }
}
