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

    public bool References(string assemblyName)
    {
        if (!_reader.HasMetadata)
        {
            return false;
        }

        var metadata = _reader.GetMetadataReader();
        return metadata.AssemblyReferences.Any(h => metadata.GetString(metadata.GetAssemblyReference(h).Name) == assemblyName);
    }

    public void Dispose()
    {
        _reader.Dispose();
        _stream.Dispose();
    }
}
