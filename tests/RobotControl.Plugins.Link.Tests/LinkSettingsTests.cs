using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Link.Tests;

public sealed class LinkSettingsTests
{
    [Theory]
    [InlineData("nats://127.0.0.1:4222")]
    [InlineData("nats://localhost:4222")]
    [InlineData("nats://[::1]:4222")]
    public void A_plain_text_link_on_the_loopback_interface_is_accepted(string url)
    {
        using var link = new LinkOutPlugin(new LinkOutSettings { Url = url }, PluginContext.Standalone("out"));
        Assert.Equal(["value"], link.Signals);
    }

    [Fact]
    public void A_plain_text_link_off_the_loopback_interface_is_refused_unless_allowed()
    {
        var remote = new LinkInSettings { Url = "nats://192.168.1.20:4222" };

        var refused = Assert.Throws<SettingsException>(() => new LinkInPlugin(remote, PluginContext.Standalone("from_robot")));
        Assert.Equal(
            "'from_robot': invalid settings: url: 'nats://192.168.1.20:4222': 192.168.1.20 is not the loopback interface and the link is plain text (samples and credentials unencrypted); set allow_plaintext_remote to true to use it anyway",
            refused.Message);
        using var allowed = new LinkInPlugin(remote with { AllowPlaintextRemote = true }, PluginContext.Standalone("from_robot"));
        Assert.Equal(LinkInPlugin.NoSampleAgeMs, allowed.GetOutput("sample_age_ms"));
    }

    [Theory]
    [InlineData("x,age", "age,z", "ages: 'z' is not one of the link's signals (x, age)")]
    [InlineData("x,age", "age,age", "ages: 'age' is listed twice")]
    public void Ages_that_are_not_the_links_signals_get_one_line_naming_the_setting(string signals, string ages, string expected)
    {
        var error = Assert.Throws<SettingsException>(() => new LinkInPlugin(new LinkInSettings { Signals = signals, Ages = ages }, PluginContext.Standalone("from_surgeon")));
        Assert.Equal($"'from_surgeon': invalid settings: {expected}", error.Message);
    }

    [Theory]
    [InlineData("url", "tls://127.0.0.1:4222", "url: 'tls://127.0.0.1:4222': tls:// is not supported yet (plain nats:// only; TLS is not done yet, see docs/link.md)")]
    [InlineData("url", "nats://me:secret@127.0.0.1:4222", "url: 'nats://me:secret@127.0.0.1:4222': give credentials in user/password or token, not in the URL")]
    [InlineData("signals", "x,y,x", "signals: 'x' is listed twice")]
    [InlineData("signals", "x,,y", "signals: '' is not a signal name (letters, digits, _ and .)")]
    [InlineData("signals", "x,sample_age_ms", "signals: 'sample_age_ms' is the name of one of the link's own ports")]
    [InlineData("subject", "rc.*.link", "subject: 'rc.*.link' is not a subject to publish on (dot-separated tokens, no wildcards or spaces)")]
    [InlineData("token", "both", "token: give user and password or a token, not both")]
    public void A_bad_setting_gets_one_line_naming_it(string setting, string value, string expected)
    {
        var settings = setting switch
        {
            "url" => new LinkOutSettings { Url = value },
            "signals" => new LinkOutSettings { Signals = value },
            "subject" => new LinkOutSettings { Subject = value },
            _ => new LinkOutSettings { User = "me", Password = "p", Token = "t" },
        };

        var error = Assert.Throws<SettingsException>(() => new LinkOutPlugin(settings, PluginContext.Standalone("to_robot")));
        Assert.Equal($"'to_robot': invalid settings: {expected}", error.Message);
    }
}
