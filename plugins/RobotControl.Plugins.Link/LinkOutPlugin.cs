using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Link;

/// <summary>
/// The sending end of a link: each tick its inputs (one per signal) go into a sample with a sequence number and the
/// tick's loop and wall-clock times, encoded into a preallocated frame queued for the sender thread, which publishes
/// it on the subject. The tick never allocates and never waits: when the sender is behind, the oldest queued sample
/// is dropped and counted (<c>dropped</c>), as are the samples of a time without a server.
/// </summary>
[PluginType("link_out", Description = "Link, sending end: publishes its inputs (named signals) on a NATS subject every tick, with a sequence number and send time.")]
public sealed class LinkOutPlugin : Plugin<LinkOutSettings>, IDisposable
{
    /// <summary>The output counting samples not sent.</summary>
    public const string DroppedPort = "dropped";

    private readonly InputPort[] _inputs;
    private readonly OutputPort _connected;
    private readonly OutputPort _dropped;
    private readonly OutputPort _sequenceOut;
    private readonly double[] _values;
    private readonly FrameRing _ring;
    private readonly LinkSender _sender;
    private readonly uint _layout;
    private uint _senderId;
    private long _sequence;

    /// <summary>Creates the sending end (it connects when the loop starts).</summary>
    public LinkOutPlugin(LinkOutSettings settings, PluginContext context)
        : base(settings, context)
    {
        ArgumentNullException.ThrowIfNull(context);
        Signals = LinkSignals.Parse(Settings.Signals);
        _inputs = [.. Signals.Select(s => DeclareInput(s, "", $"{s}, sent on {Settings.Subject}"))];
        _connected = DeclareOutput(LinkInPlugin.ConnectedPort, SafeValue.Zero, "", "1 while the connection to the server is open");
        _dropped = DeclareOutput(DroppedPort, SafeValue.HoldLastFinite, "", "samples not sent: dropped from a full queue (the sender behind) or while the server was unreachable");
        _sequenceOut = DeclareOutput(LinkInPlugin.SequencePort, SafeValue.HoldLastFinite, "", "sequence number of the sample of this tick (1 for the first)");
        _values = new double[Signals.Count];
        _layout = LinkFrame.Layout(Signals);
        _ring = new FrameRing(LinkFrame.Length(Signals.Count), Settings.Queue);
        _sender = new LinkSender(Settings, context.InstanceName, _ring);
    }

    /// <summary>The signals the link carries, in port order.</summary>
    public IReadOnlyList<string> Signals { get; }

    /// <summary>True while the connection to the server is open.</summary>
    public bool IsConnected => _sender.Connected;

    /// <summary>Samples published.</summary>
    public long Sent => _sender.Sent;

    /// <summary>Samples not sent (queue overflow, no server, failed publishing).</summary>
    public long Dropped => _ring.Dropped + _sender.Unsent;

    /// <summary>The last connection or publishing error; null before any.</summary>
    public string? LastError => _sender.LastError;

    /// <inheritdoc />
    public override void Start(in TickContext context)
    {
        _senderId = (uint)Random.Shared.Next(1, int.MaxValue);
        _sender.Start();
    }

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        for (var i = 0; i < _inputs.Length; i++)
        {
            _values[i] = Read(_inputs[i]);
        }

        _sequence++;
        var wallNs = LinkFrame.UnixNs(Context.Time.GetUtcNow());
        LinkFrame.Write(_ring.BeginWrite(), _layout, _senderId, _sequence, context.Elapsed.Ticks * 100, wallNs, _values);
        _ring.EndWrite();
        _sender.Wake();
        Write(_connected, _sender.Connected ? 1 : 0);
        Write(_dropped, Dropped);
        Write(_sequenceOut, _sequence);
    }

    /// <inheritdoc />
    public override void Stop() => _sender.Dispose();

    /// <summary>Stops the sender thread (as <see cref="Stop"/>).</summary>
    public void Dispose() => _sender.Dispose();
}
