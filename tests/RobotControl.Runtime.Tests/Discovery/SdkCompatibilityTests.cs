using System.Buffers.Binary;
using System.Reflection.Metadata;
using System.Reflection.Metadata.Ecma335;
using System.Reflection.PortableExecutable;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Standard.Conditioning;
using RobotControl.Plugins.Touch;
using RobotControl.Runtime.Discovery;

namespace RobotControl.Runtime.Tests.Discovery;

public sealed class SdkCompatibilityTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("rc-sdkcompat-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    [Fact]
    public void Same_major_loads_whatever_the_minor_and_patch()
    {
        Assert.Null(SdkCompatibility.Problem("MyLab.Filters", new Version(1, 4, 2, 0), new Version(1, 0, 0, 0)));
        Assert.Null(SdkCompatibility.Problem("MyLab.Filters", new Version(1, 0, 0, 0), new Version(1, 7, 0, 0)));
    }

    [Fact]
    public void Another_major_is_refused_naming_the_plugin_and_both_versions()
    {
        var problem = SdkCompatibility.Problem("MyLab.Filters", new Version(2, 1, 0, 0), new Version(1, 3, 0, 0));
        Assert.Equal("MyLab.Filters: built against plug-in SDK 2.1.0, this host has SDK 1.3.0 (major versions differ); not loaded, rebuild it against SDK 1.x", problem);
    }

    [Fact]
    public void Host_plugins_report_the_SDK_version_they_reference()
    {
        var catalog = PluginCatalog.FromAssemblies(typeof(ClutchPlugin).Assembly);
        Assert.Equal(SdkVersion.Current, catalog.Find("clutch")!.SdkVersion);
        Assert.Equal(SdkVersion.Current, SdkCompatibility.BuiltAgainst(typeof(Plugin).Assembly));
    }

    [Fact]
    public void A_folder_plugin_built_for_another_major_is_refused_and_the_others_load()
    {
        // The Touch plug-in as built, and a copy of the standard plug-ins whose reference to the SDK says major 2.
        var touchFolder = Directory.CreateDirectory(Path.Combine(_dir, "RobotControl.Plugins.Touch")).FullName;
        File.Copy(typeof(TouchPlugin).Assembly.Location, Path.Combine(touchFolder, "RobotControl.Plugins.Touch.dll"));
        var old = Path.Combine(_dir, "RobotControl.Plugins.Standard.dll");
        File.WriteAllBytes(old, WithSdkMajor(File.ReadAllBytes(typeof(ClutchPlugin).Assembly.Location), 2));

        var catalog = new PluginCatalog();
        catalog.AddFolder(_dir);

        var host = SdkVersion.Format(SdkVersion.Current);
        var problem = Assert.Single(catalog.Problems);
        Assert.Equal($"RobotControl.Plugins.Standard ({old}): built against plug-in SDK 2.0.0, this host has SDK {host} (major versions differ); not loaded, rebuild it against SDK {SdkVersion.Current.Major}.x", problem);
        Assert.Null(catalog.Find("clutch"));
        Assert.NotNull(catalog.Find("touch"));
    }

    /// <summary>The assembly image with the major version of its RobotControl.Plugins.Sdk reference replaced.</summary>
    private static byte[] WithSdkMajor(byte[] image, ushort major)
    {
        using var pe = new PEReader(new MemoryStream(image));
        var metadata = pe.GetMetadataReader();
        var row = metadata.AssemblyReferences
            .Select(h => (Handle: h, Name: metadata.GetString(metadata.GetAssemblyReference(h).Name)))
            .Single(r => r.Name == SdkCompatibility.SdkAssemblyName).Handle;
        // AssemblyRef rows start with MajorVersion (2 bytes, little-endian).
        var offset = pe.PEHeaders.MetadataStartOffset + metadata.GetTableMetadataOffset(TableIndex.AssemblyRef)
            + ((MetadataTokens.GetRowNumber(row) - 1) * metadata.GetTableRowSize(TableIndex.AssemblyRef));
        var patched = (byte[])image.Clone();
        BinaryPrimitives.WriteUInt16LittleEndian(patched.AsSpan(offset), major);
        return patched;
    }
}
