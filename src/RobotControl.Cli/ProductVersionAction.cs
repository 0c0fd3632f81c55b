using System.CommandLine;
using System.CommandLine.Invocation;
using System.Reflection;
using RobotControl.Plugins.Sdk;

namespace RobotControl.Cli;

/// <summary><c>robotctl --version</c>: the tool's version and the plug-in SDK version it hosts.</summary>
internal sealed class ProductVersionAction : SynchronousCommandLineAction
{
    /// <summary>The tool's semantic version.</summary>
    public static string ToolVersion { get; } =
        typeof(ProductVersionAction).Assembly.GetCustomAttribute<AssemblyInformationalVersionAttribute>()?.InformationalVersion ?? "";

    /// <inheritdoc />
    public override int Invoke(ParseResult parseResult)
    {
        ArgumentNullException.ThrowIfNull(parseResult);
        parseResult.InvocationConfiguration.Output.WriteLine($"robotctl {ToolVersion} (plug-in SDK {SdkVersion.Text})");
        return 0;
    }
}
