using RobotControl.Bus.Client;

namespace RobotControl.Robot.Bus;

/// <summary>
/// The modules that take part in the cycles (present ones), with the cycle's buffers sized for them. Built by the bus
/// thread when discovery or a re-probe changes who is present and swapped in whole; the buffers are the bus thread's.
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class ActiveModules
{
    public static readonly ActiveModules None = new();

    private ActiveModules()
    {
    }

    public ActiveModules(RobotLayout layout)
    {
        Controllers = [.. layout.Controllers.Where(c => c.Present)];
        Ids = [.. Controllers.Select(c => c.Id)];
        WriteData = new byte[Ids.Length * layout.GoalLength];

        // Modules grouped by feedback length; the groups' buffers are consecutive slices of the full-state read's.
        var ordered = Controllers.GroupBy(c => c.ChannelSpan).OrderByDescending(g => g.Key).SelectMany(g => g).ToArray();
        StateIds = [.. ordered.Select(c => c.Id)];
        StateLengths = [.. ordered.Select(c => c.ChannelSpan * layout.FeedbackStride)];
        StateData = new byte[StateLengths.Sum()];
        StateReplies = new Reply[ordered.Length];
        FastReads = ordered.All(c => c.FirmwareVersion >= BusClient.FastReadFirmwareVersion);
        var (module, offset) = (0, 0);
        Groups = [.. ordered.GroupBy(c => c.ChannelSpan).Select(g =>
        {
            var members = g.ToArray();
            var length = g.Key * layout.FeedbackStride;
            var group = new FeedbackGroup(members, length, new ArraySegment<byte>(StateData, offset, members.Length * length), new ArraySegment<Reply>(StateReplies, module, members.Length));
            (module, offset) = (module + members.Length, offset + (members.Length * length));
            return group;
        })];
        StatusData = new byte[Ids.Length * RobotLayout.StatusPollLength];
        StatusReplies = new Reply[Ids.Length];
        PotData = new byte[Ids.Length * layout.PotLength];
        PotReplies = new Reply[Ids.Length];
    }

    public RobotController[] Controllers { get; } = [];

    public byte[] Ids { get; } = [];

    public bool Any => Ids.Length > 0;

    public byte[] WriteData { get; } = [];

    public byte[] StateIds { get; } = [];

    public int[] StateLengths { get; } = [];

    public byte[] StateData { get; } = [];

    public Reply[] StateReplies { get; } = [];

    public bool FastReads { get; }

    public FeedbackGroup[] Groups { get; } = [];

    public byte[] StatusData { get; } = [];

    public Reply[] StatusReplies { get; } = [];

    public byte[] PotData { get; } = [];

    public Reply[] PotReplies { get; } = [];
}

/// <summary>Modules of one feedback length, and their slices of the full-state read's buffers.</summary>
internal sealed record FeedbackGroup(RobotController[] Controllers, int Length, ArraySegment<byte> Data, ArraySegment<Reply> Replies);
