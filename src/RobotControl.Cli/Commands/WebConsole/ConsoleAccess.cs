using RobotControl.WebConsole.Server;

namespace RobotControl.Cli.Commands.WebConsole;

/// <summary>The console command's serving options: <c>--bind</c>, <c>--token</c>, <c>--allowed-host</c>, <c>--https-cert</c>, <c>--https-key</c>.</summary>
/// <param name="Bind">The <c>--bind</c> text.</param>
/// <param name="Token">The <c>--token</c>, or null (a random one).</param>
/// <param name="AllowedHosts">The <c>--allowed-host</c> names.</param>
/// <param name="Certificate">The <c>--https-cert</c> file, or null.</param>
/// <param name="Key">The <c>--https-key</c> file, or null.</param>
internal sealed record ConsoleAccess(string Bind, string? Token, IReadOnlyList<string> AllowedHosts, string? Certificate, string? Key)
{
    /// <summary>The server's options.</summary>
    /// <exception cref="FormatException">A bad bind, a short token, <c>--https-key</c> alone, a certificate that does not load (one line).</exception>
    public ConsoleServerOptions Options()
    {
        var bind = BindAddress.Parse(Bind);
        if (Token is { Length: < 8 })
        {
            throw new FormatException("--token: give at least 8 characters");
        }

        if (Key is not null && Certificate is null)
        {
            throw new FormatException("--https-key: give --https-cert too");
        }

        return new ConsoleServerOptions
        {
            Bind = bind,
            Token = Token,
            AllowedHosts = AllowedHosts,
            Certificate = Certificate is null ? null : TlsCertificate.Load(Certificate, Key),
        };
    }

    /// <summary>One line when the console serves plain HTTP off this host (the token and every command travel in clear), else null.</summary>
    public static string? Warning(ConsoleServerOptions options) =>
        options.Certificate is null && !options.Bind.IsLoopback
            ? $"console: warning: plain HTTP on {options.Bind}, off this host: the token and every command cross the network unencrypted; give --https-cert"
            : null;
}
