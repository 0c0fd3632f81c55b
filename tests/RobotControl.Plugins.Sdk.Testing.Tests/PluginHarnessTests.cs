using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Settings;
using RobotControl.Plugins.Sdk.Testing;

namespace RobotControl.Plugins.Sdk.Testing.Tests;

public sealed class PluginHarnessTests
{
    [Fact]
    public void Feeds_inputs_ticks_and_reads_outputs()
    {
        using var harness = PluginHarness.Create(c => new IntegratorPlugin(new IntegratorSettings { Gain = 2 }, c));
        harness.Set("in", 3).Tick(500);

        Assert.Equal(500, harness.TickCount);
        Assert.Equal(3.0, harness["out"], 9); // 2 * 3 per second for 0.5 s
        Assert.Equal(0.499, harness["time"], 12); // the last tick's time: tick 499 at 1 kHz
        Assert.Equal(TimeSpan.FromSeconds(0.5), harness.Clock.Elapsed);
    }

    [Fact]
    public void Starts_before_the_first_tick_and_stops_once_on_dispose()
    {
        var harness = PluginHarness.Create(c => new IntegratorPlugin(new IntegratorSettings(), c), rateHz: 100);
        Assert.Equal((0, 0), (harness.Plugin.Starts, harness.Plugin.Stops));
        harness.Run(TimeSpan.FromSeconds(1));
        Assert.Equal((1, 0, 100L), (harness.Plugin.Starts, harness.Plugin.Stops, harness.TickCount));
        harness.Dispose();
        harness.Dispose();
        Assert.Equal(1, harness.Plugin.Stops);
        Assert.Throws<ObjectDisposedException>(() => harness.Tick());
    }

    [Fact]
    public void Time_in_the_context_and_on_the_plugins_clock_advance_one_period_per_tick()
    {
        using var harness = PluginHarness.Create(c => new IntegratorPlugin(new IntegratorSettings(), c), rateHz: 250);
        var t0 = harness.Plugin.Context.Time.GetUtcNow();
        harness.Tick(10);
        Assert.Equal(TimeSpan.FromMilliseconds(4), harness.Period);
        Assert.Equal(TimeSpan.FromMilliseconds(40), harness.Plugin.Context.Time.GetUtcNow() - t0);
        Assert.Equal(0.036, harness["time"], 12);
    }

    [Fact]
    public void Out_of_range_settings_are_refused_as_the_host_refuses_them()
    {
        var ex = Assert.Throws<SettingsException>(() => PluginHarness.Create(c => new IntegratorPlugin(new IntegratorSettings { Gain = 11 }, c)));
        Assert.Contains("gain", ex.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Reads_settings_as_a_graph_file_gives_them()
    {
        Assert.Equal(4.5, PluginHarness.ReadSettings<IntegratorSettings>("""{ "gain": 4.5 }""").Gain);
        var ex = Assert.Throws<SettingsException>(() => PluginHarness.ReadSettings<IntegratorSettings>("""{ "gain": 20, "colour": 1 }"""));
        Assert.Equal(["colour", "gain"], ex.Errors.Select(e => e.Path).Order(StringComparer.Ordinal));
    }

    [Fact]
    public void Unknown_ports_name_the_port()
    {
        using var harness = PluginHarness.Create(c => new IntegratorPlugin(new IntegratorSettings(), c));
        Assert.Contains("'nope'", Assert.Throws<ArgumentException>(() => harness.Set("nope", 1)).Message, StringComparison.Ordinal);
        Assert.Contains("'nope'", Assert.Throws<ArgumentException>(() => harness["nope"]).Message, StringComparison.Ordinal);
    }

    private sealed record IntegratorSettings : PluginSettings
    {
        [Setting("Output rate per unit input.", Units = "1/s", Minimum = 0, Maximum = 10)]
        public double Gain { get; init; } = 1;
    }

    [PluginType("integrator")]
    private sealed class IntegratorPlugin : Plugin<IntegratorSettings>
    {
        private readonly InputPort _in;
        private readonly OutputPort _out;
        private readonly OutputPort _time;

        public IntegratorPlugin(IntegratorSettings settings, PluginContext context)
            : base(settings, context)
        {
            _in = DeclareInput("in");
            _out = DeclareOutput("out", SafeValue.HoldLastFinite);
            _time = DeclareOutput("time", SafeValue.HoldLastFinite, "s");
        }

        public int Starts { get; private set; }

        public int Stops { get; private set; }

        public override void Start(in TickContext context) => Starts++;

        public override void Tick(in TickContext context)
        {
            Write(_out, ReadOutput(_out) + (Settings.Gain * Read(_in) * context.PeriodSeconds));
            Write(_time, context.TimeSeconds);
        }

        public override void Stop() => Stops++;
    }
}
