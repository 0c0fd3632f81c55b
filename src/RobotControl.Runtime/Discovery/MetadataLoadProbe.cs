using System.Reflection.Metadata;
using System.Reflection.PortableExecutable;

namespace RobotControl.Runtime.Discovery;

/// <summary>Reads an assembly's reference list from its metadata without loading it.</summary>
internal sealed class MetadataLoadProbe : IDisposable
{
    private readonly FileStream _stream;
    private readonly PEReader _reader;

    public MetadataLoadProbe(string path)
    {
        _stream = File.OpenRead(path);
        _reader = new PEReader(_stream);
    }

    /// <summary>The version of the referenced assembly named <paramref name="assemblyName"/>, or null when not referenced.</summary>
    public Version? ReferencedVersion(string assemblyName)
    {
        if (!_reader.HasMetadata)
        {
            return null;
        }

        var metadata = _reader.GetMetadataReader();
        foreach (var handle in metadata.AssemblyReferences)
        {
            var reference = metadata.GetAssemblyReference(handle);
            if (metadata.GetString(reference.Name) == assemblyName)
            {
                return reference.Version;
            }
        }

        return null;
    }

    public void Dispose()
    {
        _reader.Dispose();
        _stream.Dispose();
    }
}
