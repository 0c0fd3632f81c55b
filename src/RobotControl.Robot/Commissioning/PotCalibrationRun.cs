using System.Globalization;
using RobotControl.Bus.Client;
using RobotControl.Definitions.Model;
using RobotControl.Modules;
using RobotControl.Robot.Calibration;

namespace RobotControl.Robot.Commissioning;

/// <summary>
/// The guided pot calibration of a commissioned unit, module by module (<see cref="PotCalibrator"/>'s steps): the
/// operator puts the arm in its fixture pose, each selected motor is swept and its table fitted
/// (<see cref="PotCalibrationFit"/>), written into the module and recorded in the unit file, then verified and the
/// verdict recorded. Motors the unit file has as calibrated and verified are skipped (unless <c>--redo</c>). Any
/// failure or stop: the module's motors off (read back), then one line naming the motor or module and what to do.
/// </summary>
public sealed class PotCalibrationRun(PotCalibrationSetup setup, BusClient client, TextWriter output, CancellationToken stop)
{
    /// <summary>Calibrates every selected motor not yet done; returns the exit code.</summary>
    /// <exception cref="IOException">A module or motor failed, or the run was stopped (one line; the motors are off).</exception>
    public int Run()
    {
        var calibrated = 0;
        foreach (var module in setup.Robot.Modules.Modules)
        {
            var plan = new PotSweepPlan(setup.Robot, module);
            var selected = Enumerable.Range(0, plan.Motors.Count).Where(i => setup.Joints.Includes(plan.Motors[i])).ToList();
            if (selected.Count == 0)
            {
                continue;
            }

            var recorded = setup.Unit.Module(module.Id) ?? throw new IOException($"module {module.Id} ({module.Name}) is not in {setup.UnitPath}: commission it first (robotctl commission), then run calibrate pots again");
            var pending = new List<int>();
            foreach (var i in selected)
            {
                var name = plan.Motors[i].FullName;
                if (!setup.Redo && recorded.PotCalibration?.GetValueOrDefault(name) is { Verified: true } done)
                {
                    output.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{name}: calibrated and verified on {done.Date} (worst {done.WorstDeg:F2} deg): skipped (--redo to calibrate it again)"));
                }
                else
                {
                    pending.Add(i);
                }
            }

            if (pending.Count > 0)
            {
                Calibrate(plan, recorded, pending);
                calibrated += pending.Count;
            }
        }

        output.WriteLine($"unit {setup.Unit.Unit}: {Count(calibrated, "pot")} calibrated and verified, motors off (read back); recorded in {setup.UnitPath}");
        return 0;
    }

    private void Calibrate(PotSweepPlan plan, UnitModule recorded, List<int> pending)
    {
        var calibrator = new PotCalibrator(client, plan, setup.Options, output.WriteLine, stop);
        try
        {
            AskFixture(plan);
            calibrator.Reference();
            output.WriteLine($"{calibrator.What}: homed from the tables it held, which put it off the fixture pose by {string.Join(", ", pending.Select(i => $"{plan.Motors[i].FullName} {Deg(plan.Motors[i], calibrator.Offsets[i])} deg"))}");
            var tables = new Dictionary<int, PotCalibrationTable>();
            var samples = new Dictionary<int, int>();
            foreach (var i in pending)
            {
                var m = plan.Motors[i];
                output.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{m.FullName}: sweeping its range and back at {setup.Options.SpeedFraction * m.Motor.SpeedLimitRadS * 180 / Math.PI:F0} deg/s, recording its pot against the Hall counts"));
                var measured = calibrator.Measure(i);
                var (pos0, step) = PotCalibrationFit.Span(m);
                try
                {
                    tables[i] = PotCalibrationFit.Fit(measured, pos0, step);
                }
                catch (ArgumentException ex)
                {
                    throw new IOException($"{m.FullName}: {ex.Message}; its module keeps the table it had: run calibrate pots again", ex);
                }

                samples[i] = measured.Count;
                output.WriteLine($"{m.FullName}: {measured.Count} samples, table fitted: pot {string.Join(' ', tables[i].Raw)} at {Deg(m, pos0)}..{Deg(m, pos0 + (step * (tables[i].Count - 1)))} deg");
            }

            Record(recorded, calibrator.Store(tables), pending.Select(i => (plan.Motors[i].FullName, samples[i])));
            output.WriteLine($"{calibrator.What}: {Count(tables.Count, "table")} written into its FRAM and read back, motors homed from them; recorded in {setup.UnitPath}");
            foreach (var i in pending)
            {
                Verify(calibrator, plan.Motors[i], recorded, i, tables[i]);
            }

            if (calibrator.Holds > 0)
            {
                output.WriteLine($"{calibrator.What}: {Count(calibrator.Holds, "bus hold")} acknowledged (this host was late with a frame by more than bus_watchdog)");
            }
        }
        catch (OperationCanceledException)
        {
            calibrator.Disarm();
            throw new IOException($"stopped: {calibrator.What}'s motors are off (read back); run calibrate pots again to continue (motors calibrated and verified are kept)");
        }
        catch (Exception ex) when (ex is IOException or ArgumentException)
        {
            try
            {
                calibrator.Disarm();
            }
            catch (IOException off)
            {
                throw new IOException($"{ex.Message}; and {off.Message}", ex);
            }

            throw new IOException(ex.Message.StartsWith(calibrator.What, StringComparison.Ordinal) || plan.Motors.Any(m => ex.Message.StartsWith(m.FullName, StringComparison.Ordinal)) ? ex.Message : $"{calibrator.What}: {ex.Message}", ex);
        }
    }

    private void Verify(PotCalibrator calibrator, MotorConfig m, UnitModule recorded, int index, PotCalibrationTable table)
    {
        var bound = setup.Options.VerifyBoundDeg;
        var worst = calibrator.Verify(index, table);
        var entry = recorded.PotCalibration![m.FullName];
        entry.WorstDeg = Math.Round(worst, 3);
        entry.Verified = worst <= bound;
        setup.Unit.Save(setup.UnitPath, client.Time.GetUtcNow());
        if (!entry.Verified)
        {
            throw new IOException(string.Create(CultureInfo.InvariantCulture, $"{m.FullName}: its pot and its Hall position disagree by up to {worst:F2} deg in the verification sweep (bound {bound} deg): a slipping pot or coupling, or the arm was not in its fixture pose at the start; motors off; check them and run calibrate pots --redo --joints {m.FullName}"));
        }

        output.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{m.FullName}: verified, pot and Hall position agree within {worst:F2} deg over its range (bound {bound} deg)"));
    }

    private void Record(UnitModule recorded, IReadOnlyList<ParameterValue> values, IEnumerable<(string Name, int Samples)> motors)
    {
        foreach (var p in values)
        {
            recorded.Parameters[UnitFile.Key(p.Field, p.Motor)] = p.Value;
        }

        var now = client.Time.GetUtcNow();
        recorded.PotCalibration ??= [];
        foreach (var (name, samples) in motors)
        {
            recorded.PotCalibration[name] = new UnitPotCalibration { Date = now.UtcDateTime.ToString("yyyy-MM-ddTHH:mm:ssZ", CultureInfo.InvariantCulture), Samples = samples };
        }

        setup.Unit.Save(setup.UnitPath, now);
    }

    /// <summary>Asks the operator to put the module's joints in the fixture pose (with --yes, says it takes them as there).</summary>
    private void AskFixture(PotSweepPlan plan)
    {
        var pose = string.Join(", ", plan.Motors.Select((m, i) => $"{m.FullName} {plan.Reference[i] * 180 / Math.PI:F1} deg"));
        if (setup.Yes)
        {
            output.WriteLine($"module {plan.Module.Id} ({plan.Module.Name}): taking it as in its fixture pose ({pose})");
            return;
        }

        output.WriteLine($"module {plan.Module.Id} ({plan.Module.Name}): put the arm in its fixture pose ({pose}: every joint at mid-range, the jaw half open), keep clear of it, then press Enter");
        var line = Task.Run(setup.Operator.ReadLine);
        line.Wait(stop);
        if (line.Result is null)
        {
            // The input can end because of the stop itself (the console's prompt ends its wait on it), as this wait
            // does: whichever sees it first, a stop is reported as one, with the motors off.
            stop.ThrowIfCancellationRequested();
            throw new IOException($"stopped before module {plan.Module.Id} ({plan.Module.Name}) was confirmed in its fixture pose (no more input); run calibrate pots again to continue");
        }
    }

    private static string Count(int n, string what) => n == 1 ? $"1 {what}" : $"{n} {what}s";

    private static string Deg(MotorConfig m, long counts) => string.Create(CultureInfo.InvariantCulture, $"{m.ToRadians(counts) * 180 / Math.PI:F1}");
}

/// <summary>What a pot calibration runs with: the robot file, the unit file and its path, the operator's input or --yes, the motors selected, --redo, and how it moves.</summary>
public sealed record PotCalibrationSetup(RobotDefinition Robot, UnitFile Unit, string UnitPath, TextReader Operator, bool Yes, PotSelection Joints, bool Redo, PotCalibrationOptions Options);

/// <summary>The motors <c>--joints</c> selects: <c>arm.joint</c> names or joint names (both arms); none given: every motor.</summary>
public sealed class PotSelection
{
    private readonly HashSet<string>? _names;

    private PotSelection(HashSet<string>? names) => _names = names;

    /// <summary>The selection <paramref name="joints"/> names (null: every motor).</summary>
    /// <exception cref="ArgumentException">A name no motor of <paramref name="robot"/> has (the line lists the known ones).</exception>
    public static PotSelection Parse(RobotDefinition robot, string? joints)
    {
        ArgumentNullException.ThrowIfNull(robot);
        if (joints is null)
        {
            return new PotSelection(null);
        }

        var motors = robot.Modules.Modules.SelectMany(module => module.Motors.Select(m => new MotorConfig(robot, module, m))).ToList();
        var names = joints.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries).ToHashSet(StringComparer.Ordinal);
        var unknown = names.Where(n => !motors.Any(m => m.FullName == n || m.Name == n)).ToList();
        return unknown.Count > 0 || names.Count == 0
            ? throw new ArgumentException($"--joints '{joints}': {(names.Count == 0 ? "no motor named" : $"no motor is named {string.Join(", ", unknown)}")} (known: {string.Join(", ", motors.Select(m => m.FullName))}, or a joint name for both arms)")
            : new PotSelection(names);
    }

    /// <summary>True when <paramref name="motor"/> is selected.</summary>
    public bool Includes(MotorConfig motor) => _names is null || _names.Contains(motor.FullName) || _names.Contains(motor.Name);
}
