namespace RobotControl.Plugins.Link.Tests;

public sealed class LinkFrameTests
{
    private static readonly uint Layout = LinkFrame.Layout(["x", "y"]);

    [Fact]
    public void A_frame_decodes_to_what_was_encoded()
    {
        var frame = new byte[LinkFrame.Length(2)];
        LinkFrame.Write(frame, Layout, sender: 77, sequence: 123_456_789_012, loopNs: 5_000_000, wallNs: 1_800_000_000_000_000_000, [1.5, -2.25]);
        var sample = default(LinkSample);

        Assert.Null(LinkFrame.Read(frame, Layout, 2, ref sample));
        Assert.Equal(52, frame.Length);
        Assert.Equal(LinkFrame.Version, frame[0]);
        Assert.Equal(77u, sample.Sender);
        Assert.Equal(123_456_789_012, sample.Sequence);
        Assert.Equal(5_000_000, sample.LoopNs);
        Assert.Equal(1_800_000_000_000_000_000, sample.WallNs);
        Assert.Equal(1.5, sample.Values[0]);
        Assert.Equal(-2.25, sample.Values[1]);
    }

    [Fact]
    public void Each_kind_of_bad_frame_is_named_and_leaves_the_sample_as_it_was()
    {
        var good = new byte[LinkFrame.Length(2)];
        LinkFrame.Write(good, Layout, 1, 9, 0, 0, [3, 4]);
        var sample = default(LinkSample);
        Assert.Null(LinkFrame.Read(good, Layout, 2, ref sample));

        var otherVersion = (byte[])good.Clone();
        otherVersion[0] = 2;
        var threeSignals = new byte[LinkFrame.Length(3)];
        LinkFrame.Write(threeSignals, LinkFrame.Layout(["x", "y", "z"]), 1, 10, 0, 0, [1, 2, 3]);
        var otherNames = new byte[LinkFrame.Length(2)];
        LinkFrame.Write(otherNames, LinkFrame.Layout(["y", "x"]), 1, 10, 0, 0, [1, 2]);

        Assert.Equal("3 bytes, shorter than the 36-byte header", LinkFrame.Read([1, 2, 3], Layout, 2, ref sample));
        Assert.Equal("format version 2, this end reads version 1", LinkFrame.Read(otherVersion, Layout, 2, ref sample));
        Assert.Equal("3 signals, this end has 2", LinkFrame.Read(threeSignals, Layout, 2, ref sample));
        Assert.Equal("51 bytes, 52 expected for 2 signals", LinkFrame.Read(good.AsSpan(0, 51), Layout, 2, ref sample));
        Assert.StartsWith("signal names differ", LinkFrame.Read(otherNames, Layout, 2, ref sample), StringComparison.Ordinal);
        Assert.Equal(9, sample.Sequence);
        Assert.Equal(3, sample.Values[0]);
    }
}
