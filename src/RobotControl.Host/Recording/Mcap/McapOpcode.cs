namespace RobotControl.Host.Recording.Mcap;

/// <summary>The record types of an MCAP file (the first byte of every record), as the MCAP specification numbers them.</summary>
public enum McapOpcode : byte
{
    /// <summary>Profile and library, first record of a file.</summary>
    Header = 0x01,

    /// <summary>Where the summary section starts and its CRC, last record of a file.</summary>
    Footer = 0x02,

    /// <summary>A message schema (here a JSON Schema).</summary>
    Schema = 0x03,

    /// <summary>A topic, its schema and message encoding.</summary>
    Channel = 0x04,

    /// <summary>One message on a channel.</summary>
    Message = 0x05,

    /// <summary>A run of records (here uncompressed) with its CRC.</summary>
    Chunk = 0x06,

    /// <summary>Times and offsets of one channel's messages in the chunk before it.</summary>
    MessageIndex = 0x07,

    /// <summary>Where a chunk is and what it holds (summary section).</summary>
    ChunkIndex = 0x08,

    /// <summary>A file carried in the recording (robot file, graph, URDF).</summary>
    Attachment = 0x09,

    /// <summary>Where an attachment is (summary section).</summary>
    AttachmentIndex = 0x0A,

    /// <summary>Counts and time range of the whole file (summary section).</summary>
    Statistics = 0x0B,

    /// <summary>Named key-value pairs.</summary>
    Metadata = 0x0C,

    /// <summary>Where a metadata record is (summary section).</summary>
    MetadataIndex = 0x0D,

    /// <summary>Where each group of summary records starts.</summary>
    SummaryOffset = 0x0E,

    /// <summary>End of the data section, with its CRC.</summary>
    DataEnd = 0x0F,
}
