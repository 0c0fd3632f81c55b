using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Mirroring;

/// <summary>
/// Mirroring in joint space: the affine map q'_j = s_j q_j + c_j (s_j = ±1, c_j = 0 or π) under which the arm is
/// reflected in a plane through the base origin: every frame origin and the tool axis of FK(q') are the mirror images of
/// those of FK(q), and where the DH frames allow it the whole tool pose (rotation M R M as in <see cref="ArmMirror"/>),
/// see <see cref="MatchesToolRotation"/>. It exists when the plane is a symmetry of the chain at q = 0, as the y-normal
/// plane is for both robots: for CRB-1.0 it negates yaw and elbow and turns the roll to π - roll (s = (-1, 1, -1, -1), c = (0, 0, 0, π): the tool
/// frame's x axis is normal to the mirror plane at q = 0). The map is found once
/// at construction by checking every sign/offset choice on sample joint vectors, so it is derived from the DH table,
/// not assumed.
/// <para>
/// Why the left arm mirrors Cartesian targets rather than joints: q' generally leaves the joint ranges (the CRB elbow
/// turns negative, an inverted elbow), so the left arm is built as a mirror image whose joints take the model's joint
/// vector unchanged. This map converts between that mirror-built convention and a same-handed description of the left
/// arm (e.g. for a 3D view that draws both arms with one right-handed model).
/// </para>
/// Immutable; <see cref="Mirror"/> is allocation-free and thread-safe.
/// </summary>
public sealed class JointSpaceMirror
{
    private const double MatchTolerance = 1e-9;

    private readonly double[] _sign;
    private readonly double[] _offset;

    /// <summary>Finds the joint-space mirror of <paramref name="chain"/> for the plane with normal <paramref name="planeNormal"/>.</summary>
    /// <exception cref="ArgumentException">The plane is not a symmetry of the chain (no such map exists).</exception>
    public JointSpaceMirror(KinematicChain chain, Vector3d planeNormal)
    {
        ArgumentNullException.ThrowIfNull(chain);
        var length = planeNormal.Length;
        if (!(length > 1e-9) || !double.IsFinite(length))
        {
            throw new ArgumentException("the mirror plane normal must be a finite, non-zero vector", nameof(planeNormal));
        }

        var normal = planeNormal / length;
        var n = chain.JointCount;
        if (n > 10)
        {
            throw new ArgumentException($"joint-space mirroring searches 4^n choices; {n} joints are too many", nameof(chain));
        }

        Chain = chain;
        _sign = new double[n];
        _offset = new double[n];
        if (!Search(chain, normal, _sign, _offset, out var matchesToolRotation))
        {
            throw new ArgumentException($"{chain.Name}: the plane with normal {planeNormal} is not a symmetry of the chain; no joint-space mirror exists", nameof(planeNormal));
        }

        MatchesToolRotation = matchesToolRotation;
    }

    /// <summary>The chain mirrored.</summary>
    public KinematicChain Chain { get; }

    /// <summary>
    /// True when the map mirrors the whole tool pose (CRB-1.0); false when it mirrors the arm's geometry (every frame
    /// origin and the tool's z axis) but the tool frame's x/y axes, fixed by the DH convention, come out turned about
    /// the tool axis (LB-1.0: its tool frame's x/y do not respect the mirror plane at q = 0).
    /// </summary>
    public bool MatchesToolRotation { get; }

    /// <summary>s_j, the sign applied to joint j.</summary>
    public ReadOnlySpan<double> Signs => _sign;

    /// <summary>c_j, the offset (0 or π) added to joint j.</summary>
    public ReadOnlySpan<double> Offsets => _offset;

    /// <summary>Writes q' = s ∘ q + c: the joint vector whose tool pose is the mirror image of <paramref name="joints"/>'s. An involution.</summary>
    public void Mirror(ReadOnlySpan<double> joints, Span<double> mirrored)
    {
        var n = _sign.Length;
        if (joints.Length < n || mirrored.Length < n)
        {
            throw new ArgumentException($"joint vectors need {n} values");
        }

        for (var j = 0; j < n; j++)
        {
            // s (s q + c) + c = q + (s + 1) c: an involution when c = 0 or s = -1, which Search guarantees.
            mirrored[j] = Math.IEEERemainder((_sign[j] * joints[j]) + _offset[j], 2 * Math.PI);
        }
    }

    private static bool Search(KinematicChain chain, Vector3d normal, double[] sign, double[] offset, out bool matchesToolRotation)
    {
        // Prefer a map that mirrors the whole tool pose; else one that mirrors the arm's geometry (every frame origin
        // and the tool axis) while the tool frame's x/y, fixed by the DH convention, end up turned about that axis.
        foreach (var fullPose in new[] { true, false })
        {
            if (SearchWith(chain, normal, sign, offset, fullPose))
            {
                matchesToolRotation = fullPose;
                return true;
            }
        }

        matchesToolRotation = false;
        return false;
    }

    private static bool SearchWith(KinematicChain chain, Vector3d normal, double[] sign, double[] offset, bool fullPose)
    {
        var n = chain.JointCount;
        var samples = SampleVectors(n);
        var state = chain.CreateState();
        var frames = chain.RowCount + 1;
        var expected = samples.Select(q =>
        {
            state.Update(q);
            var origins = Enumerable.Range(0, frames).Select(f => ArmMirror.Reflect(state.Origin(f), normal)).ToArray();
            return (Origins: origins, Tool: ArmMirror.Reflect(state.ToolPose, normal));
        }).ToArray();
        var candidate = new double[n];

        // Fewest π offsets first, so the plainest map wins; an offset only goes with a sign flip (q -> c - q is an
        // involution, q -> q + π is not).
        var masks = Enumerable.Range(0, 1 << n).OrderBy(m => System.Numerics.BitOperations.PopCount((uint)m)).ThenBy(m => m).ToArray();
        foreach (var offsetMask in masks)
        {
            foreach (var signMask in masks)
            {
                if ((offsetMask & ~signMask) != 0)
                {
                    continue;
                }

                for (var j = 0; j < n; j++)
                {
                    sign[j] = (signMask & (1 << j)) != 0 ? -1 : 1;
                    offset[j] = (offsetMask & (1 << j)) != 0 ? Math.PI : 0;
                }

                var all = true;
                for (var s = 0; s < samples.Length && all; s++)
                {
                    for (var j = 0; j < n; j++)
                    {
                        candidate[j] = (sign[j] * samples[s][j]) + offset[j];
                    }

                    state.Update(candidate);
                    all = Close(state.ToolPose.Rotation.Z, expected[s].Tool.Rotation.Z)
                        && (!fullPose || (Close(state.ToolRotation.X, expected[s].Tool.Rotation.X) && Close(state.ToolRotation.Y, expected[s].Tool.Rotation.Y)));
                    for (var f = 0; f < frames && all; f++)
                    {
                        all = Close(state.Origin(f), expected[s].Origins[f]);
                    }
                }

                if (all)
                {
                    return true;
                }
            }
        }

        return false;
    }

    private static double[][] SampleVectors(int n)
    {
        // Fixed, irrational-looking angles: a spurious match on all of them is practically impossible.
        var samples = new double[3][];
        for (var s = 0; s < samples.Length; s++)
        {
            samples[s] = new double[n];
            for (var j = 0; j < n; j++)
            {
                samples[s][j] = Math.Sin((1.7 * (j + 1)) + (2.3 * (s + 1))) * 1.3;
            }
        }

        return samples;
    }

    private static bool Close(Vector3d a, Vector3d b) => (a - b).Length <= MatchTolerance * Math.Max(1, a.Length);
}
