using System.Net;
using NATS.Client.Core;

namespace RobotControl.Plugins.Link;

/// <summary>
/// The server URL and subject of a link, checked once (at settings validation), and the client options built from
/// them: plain text only (<c>nats://</c>), a host off the loopback interface only when allowed, credentials as set.
/// </summary>
internal static class LinkEndpoint
{
    /// <summary>A problem with <paramref name="url"/>, or null when it may be used; <paramref name="allowWith"/> says how a plain-text remote server is allowed.</summary>
    public static string? Check(string url, bool allowPlaintextRemote, string allowWith = "set allow_plaintext_remote to true")
    {
        if (!Uri.TryCreate(url, UriKind.Absolute, out var uri) || uri.Host.Length == 0)
        {
            return $"'{url}' is not a URL (nats://host:port)";
        }

        if (uri.Scheme is "tls" or "wss" or "ws")
        {
            return $"'{url}': {uri.Scheme}:// is not supported yet (plain nats:// only; TLS is not done yet, see docs/link.md)";
        }

        if (uri.Scheme != "nats")
        {
            return $"'{url}': the scheme must be nats://";
        }

        if (uri.UserInfo.Length > 0)
        {
            return $"'{url}': give credentials in user/password or token, not in the URL";
        }

        if (!IsLoopback(uri.Host) && !allowPlaintextRemote)
        {
            return $"'{url}': {uri.Host} is not the loopback interface and the link is plain text (samples and credentials unencrypted); {allowWith} to use it anyway";
        }

        return null;
    }

    /// <summary>A problem with <paramref name="subject"/> (a publish subject: no wildcards, no empty tokens), or null.</summary>
    public static string? CheckSubject(string subject)
    {
        if (string.IsNullOrEmpty(subject))
        {
            return null; // the Required check names it
        }

        foreach (var token in subject.Split('.'))
        {
            if (token.Length == 0 || token.Contains('*', StringComparison.Ordinal) || token == ">" || token.Any(char.IsWhiteSpace))
            {
                return $"'{subject}' is not a subject to publish on (dot-separated tokens, no wildcards or spaces)";
            }
        }

        return null;
    }

    /// <summary>True for localhost and the loopback addresses (127.0.0.0/8, ::1).</summary>
    public static bool IsLoopback(string host) =>
        host.Equals("localhost", StringComparison.OrdinalIgnoreCase)
        || (IPAddress.TryParse(host.Trim('[', ']'), out var address) && IPAddress.IsLoopback(address));

    /// <summary>The client options of a link (the settings were checked).</summary>
    public static NatsOpts Options(LinkSettings settings, string instanceName) => Options(settings.Url, instanceName) with
    {
        AuthOpts = NatsAuthOpts.Default with
        {
            Username = settings.User.Length > 0 ? settings.User : null,
            Password = settings.Password.Length > 0 ? settings.Password : null,
            Token = settings.Token.Length > 0 ? settings.Token : null,
        },
    };

    /// <summary>The client options of a connection to <paramref name="url"/> (checked), without credentials: reconnecting by itself, never giving up.</summary>
    public static NatsOpts Options(string url, string name) => NatsOpts.Default with
    {
        Url = url,
        Name = name,
        RetryOnInitialConnect = true,
        MaxReconnectRetry = -1,
        ReconnectWaitMin = TimeSpan.FromMilliseconds(50),
        ReconnectWaitMax = TimeSpan.FromSeconds(1),
        ReconnectJitter = TimeSpan.FromMilliseconds(20),
        ConnectTimeout = TimeSpan.FromSeconds(2),
        PublishTimeoutOnDisconnected = true,
        CommandTimeout = TimeSpan.FromMilliseconds(500),
    };
}
