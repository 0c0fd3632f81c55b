using System.Text;
using System.Text.Json;
using RobotControl.Definitions.Model;
using RobotControl.Host.Safety;

namespace RobotControl.Host.Tests.Safety;

/// <summary>The safety section of a run report: its JSON (field names, rounding, non-finite values), its console lines and the time at a level.</summary>
public sealed class SafetyReportTests
{
    private static readonly SafetyReport.Level[] Levels =
    [
        new(-0.123456, RunLevel.Init, RunLevel.Homing, "session", "homing from the joint pots"),
        new(0.25, RunLevel.Homing, RunLevel.PedalUp, "session", "motors on"),
        new(1.0, RunLevel.PedalUp, RunLevel.PedalDown, "pedal", "pedal down"),
        new(2.3456789, RunLevel.PedalDown, RunLevel.EStop, "supervisor", "over_current right.elbow: torque_off"),
    ];

    private static readonly SafetyReport.TripEntry[] TwoTrips =
    [
        new(1.50004, SafetyCheck.HostStall, string.Empty, 23.1234567, 10, "ms", SafeState.Hold, Soft: true),
        new(2.3456789, SafetyCheck.OverCurrent, "right.elbow", 1.23456789, 1.1875, "A", SafeState.TorqueOff),
    ];

    [Fact]
    public void The_json_names_every_field_and_rounds_times_to_4_and_values_to_6_decimals()
    {
        var report = new SafetyReport(RunLevel.EStop, Levels, TwoTrips, 7, 0.01234567, 1.3456789, 2);

        Assert.Equal(
            """{"safety":{"final_run_level":"E_STOP","run_levels":[""" +
            """{"time_s":-0.1235,"from":"INIT","to":"HOMING","source":"session","reason":"homing from the joint pots"},""" +
            """{"time_s":0.25,"from":"HOMING","to":"PEDAL_UP","source":"session","reason":"motors on"},""" +
            """{"time_s":1,"from":"PEDAL_UP","to":"PEDAL_DOWN","source":"pedal","reason":"pedal down"},""" +
            """{"time_s":2.3457,"from":"PEDAL_DOWN","to":"E_STOP","source":"supervisor","reason":"over_current right.elbow: torque_off"}],"trips":[""" +
            """{"time_s":1.5,"check":"host_stall","joint":"","measured":23.123457,"limit":10,"unit":"ms","action":"hold","soft":true},""" +
            """{"time_s":2.3457,"check":"over_current","joint":"right.elbow","measured":1.234568,"limit":1.1875,"unit":"A","action":"torque_off","soft":false}],"step_cap_hits":7,"largest_capped_step_rad":0.012346,"pedal_down_s":1.3457,"re_engagements":2}}""",
            Json(report));
    }

    [Fact]
    public void A_non_finite_measured_value_or_limit_is_written_as_a_string()
    {
        var report = new SafetyReport(
            RunLevel.EStop,
            [],
            [new(0.5, SafetyCheck.NonFinite, "setpoint", double.NaN, double.PositiveInfinity, "rad", SafeState.Hold), new(0.6, SafetyCheck.NonFinite, "right.elbow", double.NegativeInfinity, 0, "rad", SafeState.Hold)],
            0,
            0);

        using var doc = JsonDocument.Parse(Json(report));
        var trips = doc.RootElement.GetProperty("safety").GetProperty("trips");
        Assert.Equal(("NaN", "Infinity"), (trips[0].GetProperty("measured").GetString(), trips[0].GetProperty("limit").GetString()));
        Assert.Equal("-Infinity", trips[1].GetProperty("measured").GetString());
        Assert.Equal(0, trips[1].GetProperty("limit").GetDouble());
        Assert.Equal(JsonValueKind.Array, doc.RootElement.GetProperty("safety").GetProperty("run_levels").ValueKind);
        Assert.Equal(0, doc.RootElement.GetProperty("safety").GetProperty("run_levels").GetArrayLength());
        Assert.Equal((0, 0), (doc.RootElement.GetProperty("safety").GetProperty("pedal_down_s").GetDouble(), doc.RootElement.GetProperty("safety").GetProperty("re_engagements").GetInt32()));
    }

    [Fact]
    public void The_report_of_a_supervisor_gives_its_levels_and_trips_in_seconds_from_its_origin()
    {
        using var lb = new SupervisedLb();
        var supervisor = lb.Supervisor;
        lb.Cycles(10);
        var origin = lb.Clock.GetTimestamp();
        supervisor.SetOrigin(origin);
        Assert.Equal(origin, supervisor.Origin);
        supervisor.PedalDown("console");
        lb.CyclesFor(TimeSpan.FromMilliseconds(100));
        lb.Stall(TimeSpan.FromMilliseconds(20));
        var stallEnd = lb.Now;
        lb.Cycles(1);
        var end = lb.Now;

        var report = SafetyReport.Of(supervisor, end, reEngagements: 3);

        Assert.Equal(RunLevel.PedalUp, report.FinalRunLevel);
        var history = supervisor.History;
        Assert.Equal(history.Count, report.RunLevels.Count);
        for (var i = 0; i < history.Count; i++)
        {
            var (h, l) = (history[i], report.RunLevels[i]);
            Assert.Equal((h.From, h.To, h.Source, h.Reason), (l.From, l.To, l.Source, l.Reason));
            Assert.Equal((h.Timestamp - origin) / (double)lb.Clock.TimestampFrequency, l.TimeSeconds, 12);
        }

        Assert.True(report.RunLevels[0].TimeSeconds < 0); // homing came before the origin
        var trip = Assert.Single(report.Trips);
        Assert.Equal((SafetyCheck.HostStall, string.Empty, 20.0, 10.0, "ms", SafeState.Hold, true), (trip.Check, trip.Joint, trip.Measured, trip.Limit, trip.Unit, trip.Action, trip.Soft));
        Assert.Equal(stallEnd, trip.TimeSeconds, 12); // detected before the write after the stall
        Assert.Equal(report.RunLevels[^1].TimeSeconds - report.RunLevels[^2].TimeSeconds, report.PedalDownSeconds, 12);
        Assert.True(report.PedalDownSeconds > 0.1);
        Assert.Equal((lb.Robot.StepCapHits, lb.Robot.LargestCappedStepRad, 3), (report.StepCapHits, report.LargestCappedStepRad, report.ReEngagements));
        Assert.Equal("supervisor", Assert.Throws<ArgumentNullException>(() => SafetyReport.Of(null!)).ParamName);
    }

    [Fact]
    public void Write_refuses_no_writer()
    {
        var report = new SafetyReport(RunLevel.Init, [], [], 0, 0);
        Assert.Equal("w", Assert.Throws<ArgumentNullException>(() => report.Write(null!)).ParamName);
    }

    [Fact]
    public void The_console_lines_give_the_levels_gone_through_and_one_line_per_trip()
    {
        var report = new SafetyReport(RunLevel.EStop, Levels, TwoTrips, 7, 0.01234567, 1.3456789, 2);

        Assert.Equal(
            [
                "  safety: final run level E_STOP; levels INIT -> HOMING -> PEDAL_UP -> PEDAL_DOWN -> E_STOP; step cap hits 7; trips 2 (1 soft); 1.346 s at PEDAL_DOWN; re-engaged 2",
                "       1.500 s  host_stall: 23.12 ms (limit 10) -> hold, PEDAL_UP",
                "       2.346 s  over_current right.elbow: 1.235 A (limit 1.188) -> torque_off",
            ],
            report.Lines().ToList());
    }

    [Fact]
    public void Without_a_level_change_or_a_trip_the_console_line_says_so()
    {
        var report = new SafetyReport(RunLevel.Init, [], [], 0, 0);
        Assert.Equal(["  safety: final run level INIT; levels ; step cap hits 0; trips 0 (0 soft); 0.000 s at PEDAL_DOWN; re-engaged 0"], report.Lines().ToList());
    }

    [Fact]
    public void The_time_at_a_level_adds_its_episodes_from_the_start_of_the_run_to_its_end()
    {
        SafetyReport.Level[] levels =
        [
            new(-0.5, RunLevel.Init, RunLevel.PedalDown, "s", "entered before the run started: counts from 0"),
            new(1.0, RunLevel.PedalDown, RunLevel.PedalUp, "s", "1 s"),
            new(2.0, RunLevel.PedalUp, RunLevel.PedalDown, "s", "again"),
            new(2.5, RunLevel.PedalDown, RunLevel.PedalUp, "s", "0.5 s"),
            new(3.0, RunLevel.PedalUp, RunLevel.PedalDown, "s", "the last: until the end"),
        ];

        Assert.Equal(1.0 + 0.5 + 1.25, SafetyReport.TimeAt(RunLevel.PedalDown, levels, 4.25), 12);
        Assert.Equal(1.0 + 0.5, SafetyReport.TimeAt(RunLevel.PedalUp, levels, 4.25), 12);
        Assert.Equal(1.0 + 0.5, SafetyReport.TimeAt(RunLevel.PedalDown, levels, 2.5), 12); // the run ended as the second episode did
        Assert.Equal(1.0 + 0.25, SafetyReport.TimeAt(RunLevel.PedalDown, levels, 2.25), 12); // ended inside the second episode
        Assert.Equal(0.75, SafetyReport.TimeAt(RunLevel.PedalDown, levels, 0.75), 12); // ended inside the first
        Assert.Equal(0, SafetyReport.TimeAt(RunLevel.PedalDown, levels, 0)); // nothing before the start of the run
        Assert.Equal(0, SafetyReport.TimeAt(RunLevel.EStop, levels, 4.25)); // never entered
        Assert.Equal(0, SafetyReport.TimeAt(RunLevel.PedalDown, [], 4.25));
        Assert.Equal("levels", Assert.Throws<ArgumentNullException>(() => SafetyReport.TimeAt(RunLevel.PedalDown, null!, 1)).ParamName);
    }

    [Fact]
    public void A_level_left_before_the_start_of_the_run_does_not_count()
    {
        SafetyReport.Level[] levels =
        [
            new(-2.0, RunLevel.Init, RunLevel.PedalDown, "s", "before the start"),
            new(-1.0, RunLevel.PedalDown, RunLevel.PedalUp, "s", "left before the start"),
        ];

        Assert.Equal(0, SafetyReport.TimeAt(RunLevel.PedalDown, levels, 5));
        Assert.Equal(5, SafetyReport.TimeAt(RunLevel.PedalUp, levels, 5));
    }

    private static string Json(SafetyReport report)
    {
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream))
        {
            w.WriteStartObject();
            report.Write(w);
            w.WriteEndObject();
        }

        return Encoding.UTF8.GetString(stream.ToArray());
    }
}
