using System.Net;
using System.Net.Http.Json;
using System.Security.Cryptography;
using System.Security.Cryptography.X509Certificates;
using System.Text.Json;
using RobotControl.WebConsole.Server;

namespace RobotControl.WebConsole.Tests.Server;

/// <summary><c>--https-cert</c>: the console serves HTTPS with a PKCS#12 or PEM certificate; a certificate without its key is one line.</summary>
[Collection(ConsoleCollection.Name)]
public sealed class TlsTests(ConsoleFixture console) : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("rc-tls").FullName;

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    [Theory]
    [InlineData("pfx")]
    [InlineData("pem")]
    public async Task The_console_serves_https_with_a_certificate_file(string form)
    {
        using var generated = Generate();
        var (cert, key) = Write(generated, form);

        using var certificate = TlsCertificate.Load(cert, key);
        await using var server = await ConsoleServer.StartAsync(console.Session, new ConsoleServerOptions { Bind = BindAddress.Parse("127.0.0.1:0"), Certificate = certificate });
        Assert.Equal("https", server.BaseUrl.Scheme);
        X509Certificate2? presented = null;
        using var handler = new HttpClientHandler
        {
            ServerCertificateCustomValidationCallback = (_, c, _, _) =>
            {
                presented = c is null ? null : new X509Certificate2(c);
                return c?.Thumbprint == generated.Thumbprint; // trusted: the one generated here
            },
        };
        using var http = new HttpClient(handler) { BaseAddress = server.BaseUrl };
        http.DefaultRequestHeaders.Authorization = new System.Net.Http.Headers.AuthenticationHeaderValue("Bearer", server.Token);

        var status = await http.GetFromJsonAsync<JsonElement>("api/status");

        Assert.Equal("LB-1.0", status.GetProperty("status").GetProperty("robot").GetString());
        Assert.Equal(generated.Thumbprint, presented?.Thumbprint);
        using var plain = new HttpClient { BaseAddress = new Uri($"http://{server.BaseUrl.Authority}/") };
        await Assert.ThrowsAnyAsync<HttpRequestException>(() => plain.GetAsync("api/status")); // no plain HTTP beside it
        presented?.Dispose();
    }

    [Fact]
    public void A_certificate_without_its_key_is_refused_with_one_line()
    {
        using var generated = Generate();
        var path = Path.Combine(_folder, "only-cert.pem");
        File.WriteAllText(path, generated.ExportCertificatePem());

        var refused = Assert.Throws<FormatException>(() => TlsCertificate.Load(path));

        Assert.Equal($"--https-cert '{path}': cannot load the certificate (not a PKCS#12 file without a password, nor a PEM certificate with its key)", refused.Message);
        Assert.DoesNotContain("BEGIN CERTIFICATE", refused.Message, StringComparison.Ordinal);
    }

    private static X509Certificate2 Generate()
    {
        using var rsa = RSA.Create(2048);
        var request = new CertificateRequest("CN=robotcontrol-console-test", rsa, HashAlgorithmName.SHA256, RSASignaturePadding.Pkcs1);
        var names = new SubjectAlternativeNameBuilder();
        names.AddIpAddress(IPAddress.Loopback);
        names.AddDnsName("localhost");
        request.CertificateExtensions.Add(names.Build());
        request.CertificateExtensions.Add(new X509EnhancedKeyUsageExtension([new Oid("1.3.6.1.5.5.7.3.1")], false));
        return request.CreateSelfSigned(DateTimeOffset.UtcNow.AddMinutes(-5), DateTimeOffset.UtcNow.AddDays(1));
    }

    private (string Cert, string? Key) Write(X509Certificate2 certificate, string form)
    {
        if (form == "pfx")
        {
            var pfx = Path.Combine(_folder, "console.pfx");
            File.WriteAllBytes(pfx, certificate.Export(X509ContentType.Pkcs12));
            return (pfx, null);
        }

        var cert = Path.Combine(_folder, "console.pem");
        var key = Path.Combine(_folder, "console.key");
        File.WriteAllText(cert, certificate.ExportCertificatePem());
        File.WriteAllText(key, certificate.GetRSAPrivateKey()!.ExportPkcs8PrivateKeyPem());
        return (cert, key);
    }
}
