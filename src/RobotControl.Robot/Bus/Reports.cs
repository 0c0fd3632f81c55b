using RobotControl.Bus.Client;
using RobotControl.Modules;

namespace RobotControl.Robot.Bus;

/// <summary>What discovery found, compared with the robot file.</summary>
/// <param name="Present">Configured modules that answered, with what they said.</param>
/// <param name="Missing">Configured modules that did not answer.</param>
/// <param name="Unknown">Modules that answered but the robot file does not list.</param>
/// <param name="Mismatched">Configured modules that answered but are not what the file says (model, motor count).</param>
public sealed record DiscoveryReport(
    IReadOnlyList<RobotController> Present,
    IReadOnlyList<RobotController> Missing,
    IReadOnlyList<PingInfo> Unknown,
    IReadOnlyList<string> Mismatched)
{
    /// <summary>True when every configured module answered as configured and nothing else did.</summary>
    public bool AllAsConfigured => Missing.Count == 0 && Unknown.Count == 0 && Mismatched.Count == 0;

    /// <summary>What is wrong: every missing, unknown and mismatched module, one finding each (present ones are not problems).</summary>
    public IReadOnlyList<DiscoveryProblem> Problems { get; } =
    [
        .. Missing.Select(c => new DiscoveryProblem(DiscoveryProblemKind.Missing, c.Id, $"MISSING  id {c.Id,3}  {c.Name}: configured in the robot file but does not answer")),
        .. Unknown.Select(u => new DiscoveryProblem(DiscoveryProblemKind.Unknown, u.Id, $"UNKNOWN  id {u.Id,3}  model {u.ModelNumber}, firmware {u.FirmwareVersion}: answers but the robot file does not list it")),
        .. Mismatched.Select(m => new DiscoveryProblem(DiscoveryProblemKind.Mismatched, null, $"MISMATCH {m}")),
    ];

    /// <summary>One line per finding: the modules found, then the problems.</summary>
    public IEnumerable<string> Lines()
    {
        foreach (var c in Present)
        {
            yield return $"found    id {c.Id,3}  {c.Name} (model {c.ModelNumber}, firmware {c.FirmwareVersion}, {c.Motors.Count} motors: {string.Join(", ", c.Motors.Select(m => m.Config.Name))})";
        }

        foreach (var p in Problems)
        {
            yield return p.Line;
        }
    }
}

/// <summary>What kind of discovery problem.</summary>
public enum DiscoveryProblemKind
{
    /// <summary>A configured module does not answer.</summary>
    Missing,

    /// <summary>A module answers that the robot file does not list.</summary>
    Unknown,

    /// <summary>A configured module answers but is not what the robot file says (model, motor count).</summary>
    Mismatched,
}

/// <summary>One discovery problem.</summary>
/// <param name="Kind">What kind.</param>
/// <param name="ModuleId">The module's bus ID, when the finding is about one ID.</param>
/// <param name="Line">The line a person reads.</param>
public sealed record DiscoveryProblem(DiscoveryProblemKind Kind, byte? ModuleId, string Line);

/// <summary>One persistent parameter that differs between a module and the robot file.</summary>
/// <param name="ModuleId">The module.</param>
/// <param name="Expected">The value the robot file implies.</param>
/// <param name="Actual">The value the module holds.</param>
public sealed record ParameterMismatch(byte ModuleId, ParameterValue Expected, long Actual)
{
    /// <inheritdoc />
    public override string ToString() => $"module {ModuleId}: {Expected.Field.Name}{(Expected.Field.Count > 1 ? $"[{Expected.Motor}]" : string.Empty)} is {Actual}, robot file says {Expected.Value} ({Expected.Meaning})";
}

/// <summary>The outcome of homing one motor from its pot.</summary>
/// <param name="Motor">The motor.</param>
/// <param name="Outcome">What happened; only <see cref="HomingOutcome.Homed"/> means the position is now the pot's.</param>
/// <param name="PotRaw">The pot reading after the request (-1: not read).</param>
/// <param name="PotPositionRad">The output angle the pot gives through the module's calibration (NaN: uncalibrated or not read).</param>
/// <param name="PositionRad">The output angle the module reports after the request (NaN: not read).</param>
/// <param name="MotorErrors">The motor's latched error bits after the request (<c>motor_error</c>).</param>
/// <param name="Detail">Why the outcome is not <see cref="HomingOutcome.Homed"/>; empty when it is.</param>
public sealed record HomingResult(
    RobotMotor Motor,
    HomingOutcome Outcome,
    int PotRaw,
    double PotPositionRad,
    double PositionRad,
    HardwareErrors MotorErrors,
    string Detail)
{
    /// <summary>True when the motor was homed and the result verified.</summary>
    public bool Succeeded => Outcome == HomingOutcome.Homed;

    /// <summary>Position minus pot, radians (NaN when either is unknown).</summary>
    public double ErrorRad => PositionRad - PotPositionRad;

    /// <inheritdoc />
    public override string ToString()
    {
        static string Deg(double rad) => double.IsNaN(rad) ? "       ?" : $"{rad * 180 / Math.PI,8:F2}";
        var verdict = Outcome switch
        {
            HomingOutcome.Homed => "homed",
            HomingOutcome.NotCalibrated => "NOT CALIBRATED",
            HomingOutcome.Refused => "REFUSED",
            HomingOutcome.VerifyFailed => "NOT VERIFIED",
            _ => "NO REPLY",
        };
        var line = $"{Motor.Config.FullName,-28} {verdict,-14} pot {(PotRaw < 0 ? "   ?" : $"{PotRaw,4}")} -> {Deg(PotPositionRad)} deg, position {Deg(PositionRad)} deg";
        if (!double.IsNaN(ErrorRad))
        {
            line += $" (diff {ErrorRad * 180 / Math.PI:F2} deg)";
        }

        return Detail.Length == 0 ? line : $"{line}: {Detail}";
    }
}
