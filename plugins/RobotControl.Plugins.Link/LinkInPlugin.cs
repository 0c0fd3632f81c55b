using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Exchange;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Link;

/// <summary>
/// The receiving end of a link: a subscriber thread decodes the samples on the subject into a latest-value slot;
/// each tick outputs the newest sample's values (one output per signal), its age in ms (wire it to the robot's
/// <c>arm.input_age_ms</c>: the master timeout applies unchanged), <c>connected</c>, and the counts of gaps,
/// reordered or duplicate samples and bad frames. Before the first sample the values are 0 and the age is
/// <see cref="NoSampleAgeMs"/>, so nothing stale ever shows as fresh. Signals listed in <c>ages</c> are ages at the
/// sending end (a Touch's sample age): each is output with the link's own age added. The tick never allocates and
/// never waits.
/// </summary>
[PluginType("link_in", Description = "Link, receiving end: outputs the named signals last received on a NATS subject, their age, and counts of gaps, reordering and bad frames.")]
public sealed class LinkInPlugin : Plugin<LinkInSettings>, IDisposable
{
    /// <summary>The age output before the first sample, ms (about 11.6 days: older than any timeout).</summary>
    public const double NoSampleAgeMs = 1e9;

    internal const string AgePort = "sample_age_ms";
    internal const string ConnectedPort = "connected";
    internal const string FreshPort = "fresh";
    internal const string SequencePort = "sequence";
    internal const string GapsPort = "gaps";
    internal const string ReorderedPort = "reordered";
    internal const string BadFramesPort = "bad_frames";

    private readonly OutputPort[] _values;
    private readonly bool[] _isAge;
    private readonly OutputPort _age;
    private readonly OutputPort _connected;
    private readonly OutputPort _fresh;
    private readonly OutputPort _sequence;
    private readonly OutputPort _gaps;
    private readonly OutputPort _reordered;
    private readonly OutputPort _badFrames;
    private readonly LatestValue<LinkSample> _latest = new();
    private readonly LinkReceiver _receiver;
    private long _shownSequence;
    private uint _shownSender;
    private TimeSpan _seenAt;
    private double _transitMs;

    /// <summary>Creates the receiving end (it connects when the loop starts).</summary>
    public LinkInPlugin(LinkInSettings settings, PluginContext context)
        : base(settings, context)
    {
        ArgumentNullException.ThrowIfNull(context);
        Signals = LinkSignals.Parse(Settings.Signals);
        var ages = LinkSignals.ParseSubset(Settings.Ages);
        _isAge = [.. Signals.Select(s => ages.Contains(s, StringComparer.Ordinal))];
        _values = [.. Signals.Select((s, i) => _isAge[i]
            ? DeclareOutput(s, SafeValue.Initial, "ms", $"{s}, an age received on {Settings.Subject}, plus this link's sample age ({NoSampleAgeMs:G} before the first sample)", NoSampleAgeMs)
            : DeclareOutput(s, SafeValue.HoldLastFinite, "", $"{s}, received on {Settings.Subject} (0 until the first sample)"))];
        _age = DeclareOutput(AgePort, SafeValue.Initial, "ms", $"age of the values: loop time since the sample arrived plus its transit (receiver's wall clock minus the sender's); {NoSampleAgeMs:G} before the first sample. Wire it to the robot's arm.input_age_ms (the master timeout)", NoSampleAgeMs);
        _connected = DeclareOutput(ConnectedPort, SafeValue.Zero, "", "1 while the connection to the server is open");
        _fresh = DeclareOutput(FreshPort, SafeValue.Zero, "", "1 while the values are younger than stale_after_ms");
        _sequence = DeclareOutput(SequencePort, SafeValue.HoldLastFinite, "", "sequence number of the sample shown (0 before the first)");
        _gaps = DeclareOutput(GapsPort, SafeValue.HoldLastFinite, "", "sequence numbers skipped (samples lost or dropped on the way)");
        _reordered = DeclareOutput(ReorderedPort, SafeValue.HoldLastFinite, "", "samples that came after a newer one or twice (not shown)");
        _badFrames = DeclareOutput(BadFramesPort, SafeValue.HoldLastFinite, "", "frames that could not be decoded (LastBadFrame says why)");
        _receiver = new LinkReceiver(Settings, context.InstanceName, Signals, context.Time, _latest);
    }

    /// <summary>The signals the link carries, in port order.</summary>
    public IReadOnlyList<string> Signals { get; }

    /// <summary>True while the connection to the server is open.</summary>
    public bool IsConnected => _receiver.Connected;

    /// <summary>Frames received (good and bad).</summary>
    public long Received => _receiver.Received;

    /// <summary>Sender runs seen (a restarted link_out is a new one).</summary>
    public long Senders => _receiver.Senders;

    /// <summary>What was wrong with the last bad frame; null before any.</summary>
    public string? LastBadFrame => _receiver.LastBadFrame;

    /// <summary>The last connection error; null before any.</summary>
    public string? LastError => _receiver.LastError;

    internal LinkReceiver Receiver => _receiver;

    /// <inheritdoc />
    public override void Start(in TickContext context) => _receiver.Start();

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        var have = _latest.TryRead(out var sample);
        if (have && (sample.Sequence != _shownSequence || sample.Sender != _shownSender))
        {
            _shownSequence = sample.Sequence;
            _shownSender = sample.Sender;
            _seenAt = context.Elapsed;
            _transitMs = sample.TransitMs;
        }

        var age = have ? (context.Elapsed - _seenAt).TotalMilliseconds + _transitMs : NoSampleAgeMs;
        var fresh = age <= Settings.StaleAfterMs;
        var show = have && (fresh || Settings.WhenStale == StaleValues.Hold);
        for (var i = 0; i < _values.Length; i++)
        {
            // An age counts the link's own: it never shows younger than the sample it came in, stale or not.
            Write(_values[i], _isAge[i] ? (have ? Math.Max(0, sample.Values[i]) + age : NoSampleAgeMs) : show ? sample.Values[i] : 0);
        }

        Write(_age, age);
        Write(_fresh, fresh ? 1 : 0);
        Write(_connected, _receiver.Connected ? 1 : 0);
        Write(_sequence, _shownSequence);
        Write(_gaps, _receiver.Gaps);
        Write(_reordered, _receiver.Reordered);
        Write(_badFrames, _receiver.BadFrames);
    }

    /// <inheritdoc />
    public override void Stop() => _receiver.Dispose();

    /// <summary>Stops the subscriber thread (as <see cref="Stop"/>).</summary>
    public void Dispose() => _receiver.Dispose();
}
