namespace RobotControl.Bus.Protocol;

/// <summary>Dynamixel Protocol 2.0 instruction codes the modules understand.</summary>
public enum Instruction : byte
{
    /// <summary>Ping: answers with model number and firmware version.</summary>
    Ping = 0x01,

    /// <summary>Read bytes of the control table.</summary>
    Read = 0x02,

    /// <summary>Write bytes of the control table.</summary>
    Write = 0x03,

    /// <summary>Register a write (checked, acknowledged) to be applied by <see cref="Action"/>.</summary>
    RegWrite = 0x04,

    /// <summary>Apply the registered write (broadcast: every module at once).</summary>
    Action = 0x05,

    /// <summary>Restore the factory parameters.</summary>
    FactoryReset = 0x06,

    /// <summary>Restart the module.</summary>
    Reboot = 0x08,

    /// <summary>Clear (option 0x02 + key 44 58 4C 22: latched errors).</summary>
    Clear = 0x10,

    /// <summary>A status (reply) packet.</summary>
    Status = 0x55,

    /// <summary>Read the same range from several modules, each answering in turn.</summary>
    SyncRead = 0x82,

    /// <summary>Write the same range of several modules in one packet (no reply).</summary>
    SyncWrite = 0x83,

    /// <summary>Sync read answered by one combined status packet, each module adding its part.</summary>
    FastSyncRead = 0x8A,

    /// <summary>Read a different range from each listed module, each answering in turn.</summary>
    BulkRead = 0x92,

    /// <summary>Write a different range of each listed module in one packet (no reply).</summary>
    BulkWrite = 0x93,

    /// <summary>Bulk read answered by one combined status packet, each module adding its part.</summary>
    FastBulkRead = 0x9A,
}

/// <summary>Well-known IDs and sizes of the framing.</summary>
public static class FrameConstants
{
    /// <summary>The broadcast ID: every module acts; only ping and sync read are answered.</summary>
    public const byte BroadcastId = 0xFE;

    /// <summary>Header FF FF FD, reserved 00, ID, length (2), instruction.</summary>
    public const int HeaderSize = 8;

    /// <summary>Bytes of a frame besides its (stuffed) parameters: header, ID, length, instruction, CRC.</summary>
    public const int Overhead = 10;

    /// <summary>Largest frame (stuffed, with header and CRC) the codec handles.</summary>
    public const int MaxFrameSize = 1024;
}
