namespace RobotControl.Plugins.Link.Stations;

/// <summary>
/// Where a robot station takes its commands (E-STOP from the surgeon's station, docs/link.md): the NATS server and the
/// station's name, whose subject is <c>rc.&lt;station&gt;.command</c>. Checked when built: one line naming what is
/// wrong, and a plain-text server off the loopback interface is refused unless allowed.
/// </summary>
public sealed record StationAddress
{
    private StationAddress(string url, string station)
    {
        Url = url;
        Station = station;
        CommandSubject = $"rc.{station}.command";
        StatusSubject = $"rc.{station}.status";
    }

    /// <summary>The NATS server.</summary>
    public string Url { get; }

    /// <summary>The robot station's name (one subject token).</summary>
    public string Station { get; }

    /// <summary>The subject its commands travel on.</summary>
    public string CommandSubject { get; }

    /// <summary>The subject it publishes its status on (<see cref="StationStatus"/>).</summary>
    public string StatusSubject { get; }

    /// <summary>The address of station <paramref name="station"/> on <paramref name="url"/>.</summary>
    /// <exception cref="FormatException">One line naming the option (<c>--link</c> or <c>--station</c>) and what is wrong.</exception>
    public static StationAddress Parse(string url, string station, bool allowPlaintextRemote = false)
    {
        ArgumentNullException.ThrowIfNull(url);
        ArgumentNullException.ThrowIfNull(station);
        if (LinkEndpoint.Check(url, allowPlaintextRemote, "add --link-plaintext-remote") is { } urlProblem)
        {
            throw new FormatException($"--link {urlProblem}");
        }

        if (station.Length == 0 || station.Any(c => !(char.IsAsciiLetterOrDigit(c) || c is '_' or '-')))
        {
            throw new FormatException($"--station '{station}': give the robot station's name (letters, digits, _ and -), e.g. lb1");
        }

        return new StationAddress(url, station);
    }
}
