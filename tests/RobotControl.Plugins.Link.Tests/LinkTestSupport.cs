using RobotControl.Plugins.Sdk;

namespace RobotControl.Plugins.Link.Tests;

/// <summary>Link ends on a test server, and waiting (with a ceiling) for what another thread does.</summary>
internal static class LinkTestSupport
{
    private static int _subjects;

    /// <summary>A subject no other test uses.</summary>
    public static string NewSubject() => $"rc.test.link{Interlocked.Increment(ref _subjects)}";

    public static LinkOutPlugin Out(string url, string subject, string signals = "x,y", string name = "out") =>
        new(new LinkOutSettings { Url = url, Subject = subject, Signals = signals }, PluginContext.Standalone(name));

    public static LinkInPlugin In(string url, string subject, string signals = "x,y", string name = "in", StaleValues whenStale = StaleValues.Hold) =>
        new(new LinkInSettings { Url = url, Subject = subject, Signals = signals, WhenStale = whenStale }, PluginContext.Standalone(name));

    public static void WaitFor(Func<bool> condition, string what, int seconds = 20)
    {
        var end = DateTime.UtcNow + TimeSpan.FromSeconds(seconds);
        while (!condition())
        {
            if (DateTime.UtcNow > end)
            {
                Assert.Fail($"timed out after {seconds} s waiting for {what}");
            }

            Thread.Sleep(2);
        }
    }
}
