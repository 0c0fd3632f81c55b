using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Standard.Conditioning;
using RobotControl.TestSupport;

namespace RobotControl.Plugins.Standard.Tests.Conditioning;

public sealed class ClutchCycleTests
{
    private static readonly string[] Channels = ["x", "y", "z", "roll", "pitch", "yaw"];

    [Fact]
    public void Over_many_presses_and_releases_no_channel_ever_jumps()
    {
        // The reference, independent of the plug-in's offset bookkeeping: on a released tick that follows a released
        // tick the target moves exactly as the device does; on a held tick and on the release tick it does not move.
        var clutch = new PluginDriver(new ClutchPlugin(new ClutchSettings(), PluginContext.Standalone("c")));
        var previousDevice = new double[Channels.Length];
        var previousTarget = new double[Channels.Length];
        var wasHeld = false;
        var presses = 0;
        for (var k = 0; k < 1200; k++)
        {
            // Five press/release cycles of different lengths; every channel moves differently and keeps moving.
            var phase = k % 240;
            var held = phase >= 100 && phase < 100 + (20 * ((k / 240) + 1));
            presses += held && !wasHeld ? 1 : 0;
            var device = new double[Channels.Length];
            for (var c = 0; c < Channels.Length; c++)
            {
                device[c] = (30 * Math.Sin((0.01 + (0.003 * c)) * k)) + (0.02 * (c + 1) * k);
                clutch.Set((Channels[c], device[c]));
            }

            clutch.Set(("clutch", held ? 1 : 0)).Tick();
            for (var c = 0; c < Channels.Length; c++)
            {
                var target = clutch[Channels[c]];
                if (k > 0)
                {
                    var expectedStep = held || wasHeld ? 0.0 : device[c] - previousDevice[c];
                    Assert.True(Math.Abs(target - previousTarget[c] - expectedStep) <= 1e-9,
                        $"tick {k}, channel {Channels[c]}: target moved {target - previousTarget[c]}, expected {expectedStep}");
                }

                previousTarget[c] = target;
                previousDevice[c] = device[c];
            }

            Assert.Equal(held ? 1.0 : 0.0, clutch["engaged"]);
            wasHeld = held;
        }

        Assert.Equal(5, presses);
    }
}
