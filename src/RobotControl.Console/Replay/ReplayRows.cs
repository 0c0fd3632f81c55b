using System.Text.Json;
using RobotControl.Host.Recording.Mcap;

namespace RobotControl.WebConsole.Replay;

/// <summary>
/// The replay's read position in a recording: the rows of the plots' ring (the graph's signals at each recorded row,
/// then each arm's commanded joints as last recorded at or before it), read from the file in time order, a chunk at a
/// time, as the playback reaches them. A seek starts a new read just before the new position (two rows' spacing, wider
/// where the recording has a gap), so the row shown there comes first with its commanded joints, and reads only the
/// chunk or two there. Used under the replay's lock.
/// </summary>
internal sealed class ReplayRows(ReplayData data) : IDisposable
{
    private readonly double[] _row = new double[data.Names.Count];
    private readonly double[] _carried = new double[data.Names.Count];
    private IEnumerator<McapMessage>? _messages = data.File.Messages([data.Signals, .. data.Joints]).GetEnumerator();
    private McapMessage? _pending;
    private double _carriedTime = double.NaN;

    /// <summary>Rows handed out since the start or the last seek.</summary>
    public long Count { get; private set; }

    /// <summary>Moves the read to <paramref name="seconds"/>: the next row is the last one recorded at or before it.</summary>
    public void Seek(double seconds)
    {
        var position = data.Ns(seconds);
        var lookback = (2 * data.RowSpacingSeconds) + 0.01;
        do
        {
            _messages?.Dispose();
            _messages = data.File.Messages([data.Signals, .. data.Joints], data.Ns(Math.Max(0, seconds - lookback))).GetEnumerator();
            _pending = null;
            _carriedTime = double.NaN;
            Array.Fill(_row, double.NaN);
            while (Next(position, out var time))
            {
                _row.CopyTo(_carried, 0);
                _carriedTime = time;
            }

            lookback *= 10; // no row in the window: a gap in the recording
        }
        while (double.IsNaN(_carriedTime) && seconds - (lookback / 10) > 0);

        Count = 0;
    }

    /// <summary>The next row recorded at or before <paramref name="upToSeconds"/> into <paramref name="row"/>; false when there is none yet.</summary>
    /// <exception cref="InvalidDataException">The chunk that holds it is damaged.</exception>
    public bool TryNext(double upToSeconds, out double time, out ReadOnlySpan<double> row)
    {
        if (!double.IsNaN(_carriedTime))
        {
            time = _carriedTime;
            row = _carried;
            _carriedTime = double.NaN;
            Count++;
            return true;
        }

        var found = Next(data.Ns(upToSeconds), out time);
        row = _row;
        Count += found ? 1 : 0;
        return found;
    }

    /// <inheritdoc />
    public void Dispose() => _messages?.Dispose();

    /// <summary>Reads messages up to the next signals row at or before <paramref name="upToNs"/>, taking the joints on the way.</summary>
    private bool Next(ulong upToNs, out double time)
    {
        time = double.NaN;
        while (true)
        {
            if (_pending is null)
            {
                if (_messages is null || !_messages.MoveNext())
                {
                    _messages?.Dispose();
                    _messages = null;
                    return false;
                }

                _pending = _messages.Current;
            }

            var message = _pending;
            if (message.LogTimeNs > upToNs)
            {
                return false; // kept for a later call
            }

            _pending = null;
            if (message.ChannelId == data.Signals)
            {
                Numbers(message.Data.Span, _row.AsSpan(0, data.SignalCount), null);
                time = data.Seconds(message.LogTimeNs);
                return true;
            }

            var at = data.SignalCount;
            for (var arm = 0; arm < data.Joints.Count; arm++)
            {
                if (data.Joints[arm] == message.ChannelId)
                {
                    Numbers(message.Data.Span, _row.AsSpan(at, data.JointCounts[arm]), "setpoint_rad"u8);
                    break;
                }

                at += data.JointCounts[arm];
            }
        }
    }

    /// <summary>The numbers of a message in order (null as NaN): every leaf, or those of the object <paramref name="within"/>.</summary>
    private static void Numbers(ReadOnlySpan<byte> json, Span<double> into, ReadOnlySpan<byte> within)
    {
        var reader = new Utf8JsonReader(json);
        var inside = within.IsEmpty;
        var depth = -1;
        var i = 0;
        while (i < into.Length && reader.Read())
        {
            switch (reader.TokenType)
            {
                case JsonTokenType.PropertyName when !inside && reader.CurrentDepth == 1 && reader.ValueTextEquals(within):
                    inside = true;
                    depth = reader.CurrentDepth + 1;
                    break;
                case JsonTokenType.EndObject when depth >= 0 && reader.CurrentDepth < depth:
                    return;
                case JsonTokenType.Number when inside:
                    into[i++] = reader.GetDouble();
                    break;
                case JsonTokenType.Null when inside:
                    into[i++] = double.NaN;
                    break;
            }
        }
    }
}
