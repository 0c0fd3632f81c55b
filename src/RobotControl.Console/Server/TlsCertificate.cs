using System.Security.Cryptography;
using System.Security.Cryptography.X509Certificates;

namespace RobotControl.WebConsole.Server;

/// <summary>The certificate of <c>--https-cert</c>: a PKCS#12 file (.pfx/.p12, no password) or PEM (the key in the same file or in <c>--https-key</c>).</summary>
public static class TlsCertificate
{
    /// <summary>Loads the certificate with its private key.</summary>
    /// <exception cref="FormatException">The file is missing, unreadable or has no private key (one line naming the option).</exception>
    public static X509Certificate2 Load(string certificatePath, string? keyPath = null)
    {
        ArgumentException.ThrowIfNullOrEmpty(certificatePath);
        foreach (var (option, path) in new[] { ("--https-cert", certificatePath), ("--https-key", keyPath) })
        {
            if (path is not null && !File.Exists(path))
            {
                throw new FormatException($"{option} '{path}': no such file");
            }
        }

        try
        {
            var pkcs12 = keyPath is null && Path.GetExtension(certificatePath).ToUpperInvariant() is ".PFX" or ".P12";
            var certificate = pkcs12
                ? X509CertificateLoader.LoadPkcs12FromFile(certificatePath, password: null)
                : X509Certificate2.CreateFromPemFile(certificatePath, keyPath);
            if (!certificate.HasPrivateKey)
            {
                certificate.Dispose();
                throw new FormatException($"--https-cert '{certificatePath}': the certificate has no private key (give it in the file or with --https-key)");
            }

            return certificate;
        }
        catch (Exception ex) when (ex is CryptographicException or IOException or UnauthorizedAccessException or ArgumentException)
        {
            throw new FormatException($"--https-cert '{certificatePath}'{(keyPath is null ? "" : $" --https-key '{keyPath}'")}: cannot load the certificate ({(ex is CryptographicException ? "not a PKCS#12 file without a password, nor a PEM certificate with its key" : "unreadable")})");
        }
    }
}
