using RobotControl.Definitions.Json;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Link;

/// <summary>The settings <see cref="LinkOutPlugin"/> and <see cref="LinkInPlugin"/> share: server, subject, signals, credentials.</summary>
public abstract record LinkSettings : PluginSettings
{
    /// <summary>The NATS server.</summary>
    [Setting("NATS server, nats://host:port (plain text; tls:// is not supported yet). A host other than the loopback interface is refused unless allow_plaintext_remote is true.", Required = true)]
    public string Url { get; init; } = "nats://127.0.0.1:4222";

    /// <summary>The subject the samples travel on.</summary>
    [Setting("NATS subject the samples travel on, e.g. rc.<station>.<name>; link_out and link_in of one link use the same subject and signals.", Required = true)]
    public string Subject { get; init; } = "rc.station.link";

    /// <summary>The signals the link carries, in order: one port each.</summary>
    [Setting("Signal names the link carries, comma-separated (one port each, at most 64); both ends list the same names in the same order.", Required = true)]
    public string Signals { get; init; } = "value";

    /// <summary>User name for user/password authentication.</summary>
    [Setting("User name for the server's user/password authentication (empty: none).")]
    public string User { get; init; } = "";

    /// <summary>Password for user/password authentication.</summary>
    [Setting("Password for the server's user/password authentication (with user).")]
    public string Password { get; init; } = "";

    /// <summary>Token for token authentication.</summary>
    [Setting("Token for the server's token authentication (empty: none; not with user).")]
    public string Token { get; init; } = "";

    /// <summary>Allows a plain-text connection to a host off the loopback interface.</summary>
    [Setting("Allow a plain-text (nats://) connection to a host other than the loopback interface: samples and credentials cross the network unencrypted.")]
    public bool AllowPlaintextRemote { get; init; }

    /// <inheritdoc />
    public override IEnumerable<JsonProblem> CheckConsistency()
    {
        if (User.Length > 0 && Token.Length > 0)
        {
            yield return new JsonProblem("token", "give user and password or a token, not both");
        }

        if (Password.Length > 0 && User.Length == 0)
        {
            yield return new JsonProblem("password", "a password needs a user");
        }

        if (LinkEndpoint.Check(Url, AllowPlaintextRemote) is { } urlProblem)
        {
            yield return new JsonProblem("url", urlProblem);
        }

        if (LinkSignals.Check(Signals) is { } signalsProblem)
        {
            yield return new JsonProblem("signals", signalsProblem);
        }

        if (LinkEndpoint.CheckSubject(Subject) is { } subjectProblem)
        {
            yield return new JsonProblem("subject", subjectProblem);
        }
    }
}

/// <summary>Settings of <see cref="LinkOutPlugin"/>.</summary>
public sealed record LinkOutSettings : LinkSettings
{
    /// <summary>Samples the loop may queue for the sender thread before the oldest is dropped.</summary>
    [Setting("Samples queued for the sender thread; when it is behind the oldest is dropped and counted.", Minimum = 2, Maximum = 4096)]
    public int Queue { get; init; } = 64;
}

/// <summary>What <see cref="LinkInPlugin"/>'s values show once the latest sample is older than <see cref="LinkInSettings.StaleAfterMs"/>.</summary>
public enum StaleValues
{
    /// <summary>The last values received (positions, setpoints: stay where you are); sample_age_ms says how old they are.</summary>
    Hold,

    /// <summary>Zero (forces, velocities: stop pushing).</summary>
    Zero,
}

/// <summary>Settings of <see cref="LinkInPlugin"/>.</summary>
public sealed record LinkInSettings : LinkSettings
{
    /// <summary>Age after which the latest sample counts as stale.</summary>
    [Setting("Age after which the latest sample is stale: fresh goes to 0 and the values follow when_stale.", Units = "ms", Minimum = 1, Maximum = 60000)]
    public double StaleAfterMs { get; init; } = 50;

    /// <summary>What the values show while stale.</summary>
    [Setting("Values while the latest sample is stale: hold (the last received) or zero.")]
    public StaleValues WhenStale { get; init; } = StaleValues.Hold;

    /// <summary>The signals that are ages (ms) at the sending end: each is output with this link's sample age added.</summary>
    [Setting("Signals that are ages in ms at the sending end (e.g. a Touch's sample_age_ms), comma-separated, each one of signals: each is output plus this link's sample age, so the age at this end counts the link too; before the first sample, and whatever when_stale says, an age is never shown younger than the link's.")]
    public string Ages { get; init; } = "";

    /// <inheritdoc />
    public override IEnumerable<JsonProblem> CheckConsistency()
    {
        foreach (var problem in base.CheckConsistency())
        {
            yield return problem;
        }

        if (LinkSignals.CheckSubset(Ages, Signals) is { } agesProblem)
        {
            yield return new JsonProblem("ages", agesProblem);
        }
    }
}
