using System.Globalization;
using System.Text.Json.Nodes;
using System.Text.RegularExpressions;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Transports;
using RobotControl.Cli.Tests.Commands.Commission;
using RobotControl.Cli.Tests.Commands.Run;
using RobotControl.Kinematics.Coupling;
using RobotControl.Modules;
using Xunit.Abstractions;

namespace RobotControl.Cli.Tests.Commands.Calibrate;

/// <summary>
/// <c>robotctl calibrate pots</c> on a unit commissioned from <c>bus-sim --factory --unit-variation</c> (the real
/// firmware, in a process of its own behind a pty): homing from the calibrated pots against the simulator's true
/// angles (its <c>truth</c> line), the same pot readings through the design curves, <c>discover --unit</c> afterwards,
/// a rerun that skips what is done, and a stop mid-sweep that leaves the motors off.
/// </summary>
[Collection(RunProcess.Collection)]
public sealed partial class PotCalibrationTests(ITestOutputHelper log) : IDisposable
{
    private const double Deg = Math.PI / 180;
    private static readonly TimeSpan Patience = RunProcess.Patience;
    private static readonly TimeSpan CalibrationPatience = TimeSpan.FromMinutes(15);
    private readonly string _units = Directory.CreateTempSubdirectory("rc-units-").FullName;

    private static string Robot => FactoryBench.Robot;

    public void Dispose() => Directory.Delete(_units, recursive: true);

    [Fact]
    public void After_commission_and_calibration_homing_from_the_pots_is_within_half_a_degree_on_every_joint_and_the_design_curves_are_not()
    {
        using var sim = FactoryBench.StartSim(out var transport);
        FactoryBench.Commission(sim, transport, "lb-0101", _units);
        using (var calibrate = Calibrate(transport, "lb-0101"))
        {
            var code = calibrate.WaitForExit(CalibrationPatience);
            log.WriteLine(calibrate.Output);
            Assert.True(code == 0, calibrate.Output);
            Assert.Contains("unit lb-0101: 12 pots calibrated and verified, motors off (read back)", calibrate.Output, StringComparison.Ordinal);
        }

        var robot = SimulatorProcess.Robot;
        var motors = robot.Modules.Modules.SelectMany(module => module.Motors.Select(m => new MotorConfig(robot, module, m))).ToList();
        var recorded = JsonNode.Parse(File.ReadAllText(Path.Combine(_units, "lb-0101.json")))!["modules"]!.AsArray()
            .SelectMany(m => m!["pot_calibration"]!.AsObject()).ToDictionary(p => p.Key, p => p.Value!);
        Assert.Equal(motors.Select(m => m.FullName).Order(), recorded.Keys.Order());
        Assert.All(recorded.Values, c => Assert.True((bool)c["verified"]! && (double)c["worst_deg"]! <= 1.5, c.ToJsonString()));

        var home = Cli.Run("home", transport, "--robot", Robot, "--margin-ms", "50");
        Assert.True(home.Code == 0, home.Output + home.Error);
        var truth = Truth(sim);
        var homed = new Dictionary<string, (int Pot, double PositionDeg)>();
        foreach (Match line in HomeLine().Matches(home.Output))
        {
            homed[line.Groups[1].Value] = (int.Parse(line.Groups[2].Value, CultureInfo.InvariantCulture), double.Parse(line.Groups[3].Value, CultureInfo.InvariantCulture));
        }

        Assert.Equal(motors.Count, homed.Count);
        var calibrated = WorstJointError(robot, motors, m => homed[m.FullName].PositionDeg - truth[m.FullName]);
        var design = WorstJointError(robot, motors, m => (m.ToRadians(PotCalibrationTable.For(m).PositionAt(homed[m.FullName].Pot)) / Deg) - truth[m.FullName]);
        log.WriteLine($"homed from the calibrated pots: worst joint error {calibrated.Deg:F2} deg ({calibrated.Where}); the same pot readings through the design curves: {design.Deg:F2} deg ({design.Where})");
        Assert.True(calibrated.Deg < 0.5, $"homed from the calibrated pots {calibrated.Deg:F2} deg off at {calibrated.Where}");
        Assert.True(design.Deg > 5, $"the design curves were only {design.Deg:F2} deg off at {design.Where}");

        var discover = Cli.Run("discover", transport, "--robot", Robot, "--unit", "lb-0101", "--units", _units, "--margin-ms", "50");
        Assert.True(discover.Code == 0, discover.Output + discover.Error);
        Assert.Contains("unit lb-0101: 6 modules as commissioned", discover.Output, StringComparison.Ordinal);
        Assert.DoesNotContain("UNIT ", discover.Output, StringComparison.Ordinal);
        Assert.DoesNotContain("PARAM ", discover.Output, StringComparison.Ordinal);
        Assert.Contains("pot_cal values are unit lb-0101's calibrated pot tables", discover.Output, StringComparison.Ordinal);

        using var again = Calibrate(transport, "lb-0101");
        Assert.Equal(0, again.WaitForExit(Patience));
        Assert.Contains("unit lb-0101: 0 pots calibrated and verified", again.Output, StringComparison.Ordinal);
        Assert.Equal(motors.Count, Regex.Count(again.Output, "skipped \\(--redo to calibrate it again\\)"));
    }

    [Fact]
    public void Nothing_moves_before_the_fixture_is_confirmed_a_stop_mid_sweep_turns_the_motors_off_in_one_line_and_bad_input_is_one_line()
    {
        var missing = Cli.Run("calibrate", "pots", Robot, "--transport", "serial:/dev/null", "--unit", "lb-none", "--units", _units);
        Cli.AssertRefused(missing, "no unit file");
        Assert.Equal(2, missing.Code);

        using var sim = FactoryBench.StartSim(out var transport);
        FactoryBench.Commission(sim, transport, "lb-0102", _units);
        var unknown = Cli.Run("calibrate", "pots", Robot, "--transport", transport, "--unit", "lb-0102", "--units", _units, "--joints", "right.knee");
        Cli.AssertRefused(unknown, "--joints 'right.knee': no motor is named right.knee");

        using (var calibrate = new RunProcess(typing: true, "calibrate", "pots", Robot, "--transport", transport, "--unit", "lb-0102", "--units", _units, "--margin-ms", "50", "--joints", "right.elbow"))
        {
            // Interactively, nothing moves until the operator says the arm is in its fixture pose.
            calibrate.WaitFor("module 2 (right upper arm): put the arm in its fixture pose (right.elbow 75.0 deg: every joint at mid-range, the jaw half open), keep clear of it, then press Enter", Patience);
            Thread.Sleep(500);
            Assert.DoesNotContain("sweeping", calibrate.Output, StringComparison.Ordinal);
            calibrate.Type(string.Empty);
            calibrate.WaitFor("right.elbow: sweeping its range", Patience);
            Thread.Sleep(1000);
            calibrate.Signal("INT");
            Assert.Equal(2, calibrate.WaitForExit(Patience));
            Assert.Contains("stopped: module 2 (right upper arm)'s motors are off (read back); run calibrate pots again", calibrate.Output, StringComparison.Ordinal);
        }

        using var client = new BusClient(LinkFactory.Open(transport), TimeProvider.System, new BusClientOptions { ResponseMargin = TimeSpan.FromMilliseconds(50) });
        var torque = new byte[1];
        Assert.True(client.Read(2, ControlTable.Firmware["torque_enable"].At(0), torque).Succeeded);
        Assert.Equal(0, torque[0]);
        var unit = JsonNode.Parse(File.ReadAllText(Path.Combine(_units, "lb-0102.json")))!["modules"]!.AsArray();
        Assert.All(unit, m => Assert.Null(m!["pot_calibration"]));
    }

    private RunProcess Calibrate(string transport, string unit, params string[] more) =>
        new(["calibrate", "pots", Robot, "--transport", transport, "--unit", unit, "--units", _units, "--yes", "--margin-ms", "50", .. more]);

    /// <summary>Every axis's true output angle, degrees, from the simulator's <c>truth</c> line.</summary>
    private static Dictionary<string, double> Truth(RunProcess sim)
    {
        var before = sim.Output.Length;
        sim.Type("truth");
        var waited = System.Diagnostics.Stopwatch.StartNew();
        while (!sim.Output[before..].Contains("truth: ", StringComparison.Ordinal) || !sim.Output[before..].Contains(" deg\n", StringComparison.Ordinal))
        {
            Assert.True(waited.Elapsed < Patience, "no truth line");
            Thread.Sleep(50);
        }

        var line = sim.Output[before..].Split('\n').First(l => l.StartsWith("truth: ", StringComparison.Ordinal));
        return line["truth: ".Length..].Split("; ").Select(p => p.Split(' ')).ToDictionary(p => p[0], p => double.Parse(p[1], CultureInfo.InvariantCulture));
    }

    /// <summary>The worst joint error (degrees) of both arms when each motor's output is off by <paramref name="errorDeg"/> (coupled motors through the inverse coupling).</summary>
    private static (double Deg, string Where) WorstJointError(Definitions.Model.RobotDefinition robot, List<MotorConfig> motors, Func<MotorConfig, double> errorDeg)
    {
        var map = new JointMotorMap(robot);
        var worst = (Deg: 0.0, Where: string.Empty);
        foreach (var arm in robot.Arms)
        {
            var actuators = new double[map.JointCount];
            foreach (var m in motors.Where(m => m.ArmName == arm.Name))
            {
                var k = map.IndexOfActuator(m.Actuator.Name);
                var error = errorDeg(m);
                if (k >= 0)
                {
                    actuators[k] = error;
                }
                else if (Math.Abs(error) > worst.Deg)
                {
                    worst = (Math.Abs(error), m.FullName); // the jaw drive: its output is the jaw angle
                }
            }

            var joints = new double[map.JointCount];
            map.ActuatorsToJoints(actuators, joints);
            for (var j = 0; j < joints.Length; j++)
            {
                if (Math.Abs(joints[j]) > worst.Deg)
                {
                    worst = (Math.Abs(joints[j]), $"{arm.Name}.{robot.Joints[j].Name} (joint)");
                }
            }
        }

        return worst;
    }

    [GeneratedRegex(@"^(\S+)\s+homed\s+pot\s+(\d+) ->\s+\S+ deg, position\s+(-?[\d.]+) deg", RegexOptions.Multiline)]
    private static partial Regex HomeLine();
}
