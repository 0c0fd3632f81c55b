namespace RobotControl.Plugins.Standard.Pedals;

/// <summary>
/// The foot-pedal box's serial protocol: every state change (and every 100 ms as a heartbeat) the box sends three
/// bytes, <c>'P'</c>, the pedal mask (bit i = pedal i+1 pressed) and the mask's complement. Garbage is skipped
/// until a valid frame lines up, so a corrupted byte costs one frame, never a wrong state.
/// </summary>
public sealed class PedalFrameParser
{
    /// <summary>The frame's first byte.</summary>
    public const byte Header = (byte)'P';

    private int _state;
    private byte _mask;

    /// <summary>Frames rejected (complement mismatch).</summary>
    public long Rejected { get; private set; }

    /// <summary>Encodes the frame for <paramref name="mask"/> (for simulated boxes and tests).</summary>
    public static byte[] Encode(byte mask) => [Header, mask, (byte)~mask];

    /// <summary>Feeds one byte; true when it completed a valid frame (then <paramref name="mask"/> holds its state).</summary>
    public bool Feed(byte b, out byte mask)
    {
        mask = 0;
        switch (_state)
        {
            case 0:
                _state = b == Header ? 1 : 0;
                return false;
            case 1:
                _mask = b;
                _state = 2;
                return false;
            default:
                _state = 0;
                if ((byte)~_mask == b)
                {
                    mask = _mask;
                    return true;
                }

                Rejected++;
                _state = b == Header ? 1 : 0;
                return false;
        }
    }
}
