using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.ClosedForm;

/// <summary>
/// Closed-form position inverse kinematics of a CRB-1.0 arm (docs/robots.md): the three position joints phi1 (shoulder yaw
/// about the base z), phi2 (shoulder pitch about the yawed -y) and phi3 (elbow) from a tool position, elbow up
/// (phi3 in 0..105°, or the file's elbow range within 0..180°) and no inverted shoulder (|phi2| ≤ 90°).
/// <para>
/// Derivation from the DH table (rows (0,0,0,0), (90°,0,0,phi1), (-90°,L1,0,phi2), (90°,0,0,phi3+90°), (0,0,L2,phi4)):
/// p = Rz(phi1) R₋y(phi2) (L1 + L2 cos phi3, L2 sin phi3, 0). So |p|² = L1² + L2² + 2 L1 L2 cos phi3 gives the elbow
/// (law of cosines; elbow up takes the non-negative acos). With v = (v1, v2) = (L1 + L2 cos phi3, L2 sin phi3), the
/// horizontal reach of the pitched upper-arm plane is h = v1 cos phi2 = sqrt(px² + py² - v2²) (h ≥ 0: no inverted
/// shoulder), then phi2 = atan2(pz, h) and phi1 = atan2(py, px) - atan2(v2, h). Taking h from the horizontal radius,
/// not asin(pz / v1), keeps the position exact to rounding near phi2 = -90° where asin loses half the digits.
/// At q = 0 the tool is at (L1 + L2, 0, 0); q = (0, -90°, 0) points it down -z.
/// </para>
/// L1 (a of DH row 3) and L2 (d of DH row 5) are read from the robot's definition; the constructor checks the table has
/// the CRB structure this derivation assumes. Allocation-free and thread-safe after construction.
/// </summary>
public sealed class CrbPositionIk
{
    /// <summary>
    /// Position tolerance, mm: a solution (joints clamped into their ranges) is accepted when it reaches the target
    /// within this distance; a target this close beyond full reach counts as on it.
    /// </summary>
    public const double ReachToleranceMm = 1e-9;

    private const double StructureTolerance = 1e-12;

    private readonly double[] _min = new double[3];
    private readonly double[] _max = new double[3];

    /// <summary>Builds the solver from <paramref name="robot"/>'s DH table and joint ranges.</summary>
    /// <exception cref="ArgumentException">The DH table does not have the CRB-1.0 structure.</exception>
    public CrbPositionIk(RobotDefinition robot)
    {
        ArgumentNullException.ThrowIfNull(robot);
        var dh = robot.Dh;
        if (dh.Count != 5)
        {
            throw new ArgumentException($"{robot.Name}: the CRB closed form needs 5 DH rows, found {dh.Count}", nameof(robot));
        }

        Expect(robot, 0, alphaDeg: 0, offsetDeg: 0, joint: -1, aZero: true, dZero: true);
        Expect(robot, 1, alphaDeg: 90, offsetDeg: 0, joint: 0, aZero: true, dZero: true);
        Expect(robot, 2, alphaDeg: -90, offsetDeg: 0, joint: 1, aZero: false, dZero: true);
        Expect(robot, 3, alphaDeg: 90, offsetDeg: 90, joint: 2, aZero: true, dZero: true);
        if (Math.Abs(dh[4].AMm) > StructureTolerance || !(dh[4].DMm > 0) || dh[4].JointIndex != 3)
        {
            throw new ArgumentException($"{robot.Name}: DH row 5 must be the tool roll (joint 4) with a = 0 and d = L2 > 0", nameof(robot));
        }

        UpperArmMm = dh[2].AMm;
        ForearmMm = dh[4].DMm;
        if (!(UpperArmMm > 0))
        {
            throw new ArgumentException($"{robot.Name}: DH row 3 must have a = L1 > 0", nameof(robot));
        }

        for (var j = 0; j < 3; j++)
        {
            _min[j] = robot.Joints[j].MinRad;
            _max[j] = robot.Joints[j].MaxRad;
        }

        // Elbow up and no inverted shoulder: the branches this closed form returns.
        _min[1] = Math.Max(_min[1], -Math.PI / 2);
        _max[1] = Math.Min(_max[1], Math.PI / 2);
        _min[2] = Math.Max(_min[2], 0);
        _max[2] = Math.Min(_max[2], Math.PI);
        if (_min[1] > _max[1] || _min[2] > _max[2])
        {
            throw new ArgumentException($"{robot.Name}: the joint ranges leave no elbow-up, non-inverted solution", nameof(robot));
        }

        var (sMax, cMax) = Math.SinCos(_max[2]);
        var (sMin, cMin) = Math.SinCos(_min[2]);
        MaxReachMm = Math.Sqrt(Square(UpperArmMm + (ForearmMm * cMin)) + Square(ForearmMm * sMin));
        MinReachMm = Math.Sqrt(Square(UpperArmMm + (ForearmMm * cMax)) + Square(ForearmMm * sMax));
    }

    /// <summary>L1, the upper arm (a of DH row 3), mm.</summary>
    public double UpperArmMm { get; }

    /// <summary>L2, the forearm to the tool point (d of DH row 5), mm.</summary>
    public double ForearmMm { get; }

    /// <summary>Largest distance from the shoulder the elbow range allows, mm.</summary>
    public double MaxReachMm { get; }

    /// <summary>Smallest distance from the shoulder the elbow range allows, mm.</summary>
    public double MinReachMm { get; }

    /// <summary>
    /// Solves for <paramref name="target"/> (mm, base frame). On success writes phi1..phi3 (radians) to
    /// <paramref name="joints"/>[0..2] and leaves the rest (the tool roll) untouched; on failure writes nothing.
    /// On the shoulder axis with the elbow straight the yaw is free: the value already in <paramref name="joints"/>[0]
    /// is kept (clamped into its range).
    /// </summary>
    public CrbIkStatus Solve(Vector3d target, Span<double> joints)
    {
        if (joints.Length < 3)
        {
            throw new ArgumentException($"needs room for 3 joints, found {joints.Length}", nameof(joints));
        }

        if (!target.IsFinite)
        {
            return CrbIkStatus.InvalidTarget;
        }

        var l1 = UpperArmMm;
        var l2 = ForearmMm;
        var distanceSquared = target.LengthSquared;
        var distance = Math.Sqrt(distanceSquared);
        if (distance > MaxReachMm + ReachToleranceMm)
        {
            return CrbIkStatus.OutOfReach;
        }

        if (distance < MinReachMm - ReachToleranceMm)
        {
            return CrbIkStatus.TooClose;
        }

        // Within the tolerance of full (or least) reach the elbow sits on its limit: acos is square-root conditioned
        // there, and a rounding-level angle would make the yaw compensate sideways.
        double elbow;
        if (MaxReachMm - distance <= ReachToleranceMm)
        {
            elbow = _min[2];
        }
        else if (distance - MinReachMm <= ReachToleranceMm)
        {
            elbow = _max[2];
        }
        else
        {
            var cosElbow = (distanceSquared - (l1 * l1) - (l2 * l2)) / (2 * l1 * l2);
            elbow = Math.Clamp(Math.Acos(Math.Clamp(cosElbow, -1.0, 1.0)), _min[2], _max[2]);
        }

        var (sinElbow, cosElbowUsed) = Math.SinCos(elbow);
        var v1 = l1 + (l2 * cosElbowUsed);
        var v2 = l2 * sinElbow;
        var horizontalSquared = (target.X * target.X) + (target.Y * target.Y);
        var h = Math.Sqrt(Math.Max(0.0, horizontalSquared - (v2 * v2)));
        double yaw;
        if (horizontalSquared <= ReachToleranceMm * ReachToleranceMm)
        {
            // On the shoulder's yaw axis (so the elbow is straight): any yaw reaches the target.
            yaw = double.IsFinite(joints[0]) ? joints[0] : 0.0;
        }
        else
        {
            yaw = Math.IEEERemainder(Math.Atan2(target.Y, target.X) - Math.Atan2(v2, h), 2 * Math.PI);
        }

        var clampedYaw = Math.Clamp(yaw, _min[0], _max[0]);
        if (clampedYaw != yaw)
        {
            // Pointing nearly straight down, h is only known to the square root of the rounding, and so is the yaw:
            // take the limit and the h that the target's horizontal position gives in that direction.
            yaw = clampedYaw;
            var (sinYaw, cosYaw) = Math.SinCos(yaw);
            h = Math.Max(0.0, (cosYaw * target.X) + (sinYaw * target.Y));
        }

        var pitch = Math.Clamp(Math.Atan2(target.Z, h), _min[1], _max[1]);

        // Accept only what reproduces the target: this refuses targets that need a joint beyond its limit, an
        // inverted shoulder or elbow (e.g. inside the cylinder the bent forearm sweeps about the yaw axis).
        if ((Position(yaw, pitch, v1, v2) - target).Length > ReachToleranceMm)
        {
            return CrbIkStatus.JointLimit;
        }

        joints[0] = yaw;
        joints[1] = pitch;
        joints[2] = elbow;
        return CrbIkStatus.Solved;
    }

    /// <summary>Tool position for (yaw, pitch) and the elbow's in-plane offsets: Rz(yaw) R₋y(pitch) (v1, v2, 0).</summary>
    private static Vector3d Position(double yaw, double pitch, double v1, double v2)
    {
        var (sinYaw, cosYaw) = Math.SinCos(yaw);
        var (sinPitch, cosPitch) = Math.SinCos(pitch);
        var reach = cosPitch * v1;
        return new Vector3d((cosYaw * reach) - (sinYaw * v2), (sinYaw * reach) + (cosYaw * v2), sinPitch * v1);
    }

    private static double Square(double x) => x * x;

    private static void Expect(RobotDefinition robot, int row, double alphaDeg, double offsetDeg, int joint, bool aZero, bool dZero)
    {
        var r = robot.Dh[row];
        const double deg = Math.PI / 180;
        var ok = Math.Abs(r.AlphaRad - (alphaDeg * deg)) < StructureTolerance
            && Math.Abs(r.ThetaOffsetRad - (offsetDeg * deg)) < StructureTolerance
            && r.JointIndex == joint
            && (!aZero || Math.Abs(r.AMm) < StructureTolerance)
            && (!dZero || Math.Abs(r.DMm) < StructureTolerance);
        if (!ok)
        {
            throw new ArgumentException(
                $"{robot.Name}: DH row {row + 1} must be (alpha {alphaDeg}°, a {(aZero ? "0" : "L1")}, d 0, theta offset {offsetDeg}°, joint {(joint < 0 ? "none" : (joint + 1).ToString(System.Globalization.CultureInfo.InvariantCulture))}) for the CRB closed form",
                nameof(robot));
        }
    }
}

/// <summary>Outcome of <see cref="CrbPositionIk.Solve"/>.</summary>
public enum CrbIkStatus
{
    /// <summary>The joints were written.</summary>
    Solved,

    /// <summary>Farther from the shoulder than the arm reaches.</summary>
    OutOfReach,

    /// <summary>Closer to the shoulder than the elbow range allows.</summary>
    TooClose,

    /// <summary>Reachable only outside the shoulder joint ranges (or with an inverted shoulder).</summary>
    JointLimit,

    /// <summary>The target holds NaN or infinity.</summary>
    InvalidTarget,
}
