using System.Runtime.Loader;
using RobotControl.Plugins.Sdk.Devices;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Standard.Pedals;
using RobotControl.Plugins.Standard.Recording;
using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.Tests.Support;
using RobotControl.TestSupport;

namespace RobotControl.Runtime.Tests.Plugins;

public sealed class RecordingAndPedalsTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("rc-runtime-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    [Fact]
    public void A_recording_of_every_signal_plays_back_into_a_graph()
    {
        var context = new PluginContext("rec", null, TimeProvider.System, _dir);
        var graph = new PluginGraph();
        var recorder = new RecorderPlugin(new RecorderSettings { Path = "out/rec.csv" }, context);
        graph.Add(new CounterSource("a"));
        graph.Add(new Gain("b", 0.5));
        graph.Add(recorder);
        graph.Connect("a.value", "b.in");
        var program = graph.Compile();
        Ticks.Run(program, 50);
        program.Stop();

        var lines = File.ReadAllLines(Path.Combine(_dir, "out/rec.csv"));
        Assert.Equal("time_s,a.value,b.out,b.force", lines[0]);
        Assert.Equal(51, lines.Length);
        Assert.Equal("0.049,49,24.5,24.5", lines[^1]);

        // Playback: the recorded b.out drives a fresh sink; at tick k (time k ms) it sees row k.
        var player = new PlaybackPlugin(new PlaybackSettings { Path = "out/rec.csv" }, new PluginContext("play", null, TimeProvider.System, _dir));
        var sink = new Gain("sink");
        var replay = new PluginGraph();
        replay.Add(player);
        replay.Add(sink);
        replay.Connect("play.b.out", "sink.in");
        Ticks.Run(replay.Compile(), 50);

        Assert.Equal(Enumerable.Range(0, 50).Select(k => k * 0.5), sink.Seen);
        Assert.Equal(0, recorder.Dropped);
    }

    [Fact]
    public void Scripted_pedals_press_and_release_on_time()
    {
        var pedals = new PluginDriver(new FootPedalsPlugin(new FootPedalsSettings { Script = "0.010:1,0.020:3,0.030:0" }, PluginContext.Standalone("p")));
        pedals.Start().Tick(15);
        Assert.Equal((1.0, 0.0), (pedals["pedal1"], pedals["pedal2"]));
        pedals.Tick(10);
        Assert.Equal((1.0, 1.0), (pedals["pedal1"], pedals["pedal2"]));
        pedals.Tick(10);
        Assert.Equal((0.0, 0.0), (pedals["pedal1"], pedals["pedal2"]));
    }

    private sealed class BytesLink(byte[] bytes) : IByteSource
    {
        private int _at;

        public int Read(Span<byte> buffer, TimeSpan timeout)
        {
            if (_at >= bytes.Length)
            {
                Thread.Sleep(1);
                return 0;
            }

            buffer[0] = bytes[_at++]; // one byte at a time, as a slow UART delivers them
            return 1;
        }

        public void Dispose()
        {
        }
    }

    [Fact]
    public void A_serial_pedal_box_is_read_on_its_own_thread_and_corrupted_frames_never_show()
    {
        byte[] wire = [.. PedalFrameParser.Encode(1), 0x00, (byte)'P', 0x02, 0x02, .. PedalFrameParser.Encode(2), .. PedalFrameParser.Encode(3)];
        var source = new SerialPedalSource(() => new BytesLink(wire));
        var pedals = new PluginDriver(new FootPedalsPlugin(new FootPedalsSettings { Source = PedalSourceKind.Serial, Transport = "serial:/dev/null" }, PluginContext.Standalone("p"), source));
        pedals.Start();
        var deadline = DateTime.UtcNow.AddSeconds(5);
        while (source.Frames < 3 && DateTime.UtcNow < deadline)
        {
            Thread.Sleep(5);
        }

        pedals.Tick();
        pedals.Plugin.Stop();

        Assert.Equal(3, source.Frames);
        Assert.Equal(1, source.Rejected);
        Assert.Equal((1.0, 1.0), (pedals["pedal1"], pedals["pedal2"]));
    }

    [Fact]
    public void Plugin_assemblies_load_from_a_folder_each_in_its_own_load_context()
    {
        var touch = typeof(RobotControl.Plugins.Touch.TouchPlugin).Assembly.Location;
        var folder = Path.Combine(_dir, "plugins", "RobotControl.Plugins.Touch");
        Directory.CreateDirectory(folder);
        File.Copy(touch, Path.Combine(folder, Path.GetFileName(touch)));

        var catalog = new PluginCatalog();
        catalog.AddFolder(Path.Combine(_dir, "plugins"));

        var type = catalog.Find("touch");
        Assert.NotNull(type);
        Assert.Empty(catalog.Problems);
        var context = AssemblyLoadContext.GetLoadContext(type.Type.Assembly);
        Assert.NotSame(AssemblyLoadContext.Default, context);
        Assert.True(typeof(Plugin).IsAssignableFrom(type.Type)); // the SDK is shared with the host
    }
}
