using System.Diagnostics;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Touch;
using RobotControl.Runtime.Graph;
using RobotControl.TestSupport;
using RobotControl.Tests.FakeHd;

namespace RobotControl.Plugins.Touch.Tests.OpenHaptics;

/// <summary>Touch instances on the fake library, and a loop paced by the wall clock (the fake servo runs in real time).</summary>
internal static class FakeTouch
{
    private static readonly TimeSpan Timeout = TimeSpan.FromSeconds(10);

    public static TouchSettings Settings(string device = "right") => new()
    {
        Backend = TouchBackendKind.Openhaptics,
        Device = device,
        LibraryPath = FakeHdLibrary.Folder,
        StaleAfterMs = 200, // tests not about staleness stay clear of a busy machine's scheduling hiccups
    };

    public static TouchPlugin Plugin(TouchSettings settings, string name = "touch") => new(settings, PluginContext.Standalone(name));

    /// <summary>Ticks (about once a millisecond) until <paramref name="done"/> holds.</summary>
    public static void TickUntil(PluginDriver driver, Func<bool> done) => Until(() => driver.Tick(), done);

    /// <summary>Ticks the program (about once a millisecond) until <paramref name="done"/> holds; returns the ticks run.</summary>
    public static long TickUntil(GraphProgram program, ref long tick, Func<bool> done)
    {
        var start = tick;
        var t = tick;
        Until(() => program.Tick(Ticks.At(t++)), done);
        tick = t;
        return t - start;
    }

    /// <summary>Ticks until device frame <paramref name="frame"/>.</summary>
    public static void TickToFrame(PluginDriver driver, string device, long frame) => TickUntil(driver, () => FakeHdLibrary.Frames(device) >= frame);

    private static void Until(Action tick, Func<bool> done)
    {
        var clock = Stopwatch.StartNew();
        while (!done())
        {
            Assert.True(clock.Elapsed < Timeout, "the fake device did not get there in time");
            tick();
            Thread.Sleep(1);
        }
    }
}
