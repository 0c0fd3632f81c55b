using RobotControl.Bus.Transports;

namespace RobotControl.Cli.Tests.Commands.Calibrate;

/// <summary>
/// The host's link to an in-process virtual bus that injects a fault once, just before the first frame the host sends
/// after <paramref name="cue"/> holds: a fault at a point of a motion (e.g. a joint 10 degrees into its sweep) rather
/// than at a time.
/// </summary>
internal sealed class FaultOnCue(IByteLink inner, Func<bool> cue, Action fault) : IByteLink
{
    /// <summary>True once the fault was injected.</summary>
    public bool Injected { get; private set; }

    public string Description => inner.Description;

    public int BaudRate => inner.BaudRate;

    public void Write(ReadOnlySpan<byte> data)
    {
        if (!Injected && cue())
        {
            Injected = true;
            fault();
        }

        inner.Write(data);
    }

    public int Read(Span<byte> buffer, TimeSpan timeout) => inner.Read(buffer, timeout);

    public void DiscardInput() => inner.DiscardInput();

    public void Dispose() => inner.Dispose();
}
