using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;

namespace RobotControl.Analysis.Workspace;

/// <summary>
/// The reachable tool-tip region of one arm model (right arm, base frame) as a <see cref="CylindricalOccupancy"/>
/// about the axis of the first position joint (fixed in the base: only fixed rows or fixed joints precede it).
/// <para>
/// Method: with the first position joint at its reference value, march a grid over the remaining position joints
/// with steps chosen so the tool tip moves less than half a cell per step (step = (h/2) / lever bound, the lever
/// bound being the link lengths beyond the joint), and mark every tip position. The last joint's positions are a
/// rotation of one point about its axis, so only the outer joints need forward kinematics. Then sweep the marked
/// set about the first joint's axis over that joint's range (an angular dilation of each cell's bitset). Joints that
/// do not position the tool stay at 0 clamped into their ranges.
/// </para>
/// </summary>
internal static class ArmWorkspaceSampler
{
    public static CylindricalOccupancy Sample(RobotDefinition robot, double cellMm, out long samples)
    {
        if (!(cellMm > 0))
        {
            throw new ArgumentOutOfRangeException(nameof(cellMm), "the voxel size must be positive");
        }

        var chain = new KinematicChain(robot);
        var joints = robot.PositionJoints.OrderBy(chain.RowOfJoint).ToArray();
        if (joints.Length == 0)
        {
            throw new ArgumentException($"{robot.Name}: no position joints");
        }

        var q0 = robot.Joints.Select(j => Math.Clamp(0.0, j.MinRad, j.MaxRad)).ToArray();
        var first = joints[0];
        var state = chain.CreateState();
        state.Update(q0);
        var reach = ReachBound(robot, chain.RowOfJoint(first));
        var occupancy = new CylindricalOccupancy(state.JointOrigin(first), state.JointAxis(first), reach, cellMm);

        var rest = joints[1..];
        var grids = rest.Select(j => JointGrid.For(robot.Joints[j], LeverBound(robot, chain.RowOfJoint(j)), cellMm)).ToArray();
        var outerCount = 1L;
        for (var i = 0; i < rest.Length - 1; i++)
        {
            outerCount *= grids[i].Count;
        }

        var inner = rest.Length > 0 ? grids[^1] : new JointGrid(0, 0, 1);
        var cos = new double[inner.Count];
        var sin = new double[inner.Count];
        for (var k = 0; k < inner.Count; k++)
        {
            (sin[k], cos[k]) = Math.SinCos(inner.At(k) - inner.At(0));
        }

        Parallel.For(0, outerCount, () => (chain.CreateState(), (double[])q0.Clone()), (outer, _, local) =>
        {
            var (s, q) = local;
            var remainder = outer;
            for (var i = rest.Length - 2; i >= 0; i--)
            {
                q[rest[i]] = grids[i].At((int)(remainder % grids[i].Count));
                remainder /= grids[i].Count;
            }

            if (rest.Length > 0)
            {
                q[rest[^1]] = inner.At(0);
            }

            s.Update(q);
            MarkArc(occupancy, s, rest.Length > 0 ? rest[^1] : -1, cos, sin);
            return local;
        }, _ => { });

        occupancy.Dilate(robot.Joints[first].MinRad - q0[first], robot.Joints[first].MaxRad - q0[first]);
        samples = outerCount * inner.Count;
        return occupancy;
    }

    /// <summary>Marks the tip as the last joint turns through its grid: tip(t) = o + r∥ + r⊥ cos t + (a × r) sin t.</summary>
    private static void MarkArc(CylindricalOccupancy occupancy, ChainState state, int lastJoint, double[] cos, double[] sin)
    {
        var tip = state.ToolPosition;
        Vector3d centre, radial, tangential;
        if (lastJoint < 0)
        {
            (centre, radial, tangential) = (tip, Vector3d.Zero, Vector3d.Zero);
        }
        else
        {
            var o = state.JointOrigin(lastJoint);
            var a = state.JointAxis(lastJoint);
            var r = tip - o;
            var along = a * Vector3d.Dot(a, r);
            centre = o + along;
            radial = r - along;
            tangential = Vector3d.Cross(a, r);
        }

        var c = centre - occupancy.Origin;
        var (u, v, w) = (occupancy.U, occupancy.V, occupancy.Axis);
        double cu = Vector3d.Dot(c, u), cv = Vector3d.Dot(c, v), cw = Vector3d.Dot(c, w);
        double ru = Vector3d.Dot(radial, u), rv = Vector3d.Dot(radial, v), rw = Vector3d.Dot(radial, w);
        double tu = Vector3d.Dot(tangential, u), tv = Vector3d.Dot(tangential, v), tw = Vector3d.Dot(tangential, w);
        for (var k = 0; k < cos.Length; k++)
        {
            var x = cu + (ru * cos[k]) + (tu * sin[k]);
            var y = cv + (rv * cos[k]) + (tv * sin[k]);
            var z = cw + (rw * cos[k]) + (tw * sin[k]);
            occupancy.Mark(Math.Sqrt((x * x) + (y * y)), z, FastAngle.Atan2(y, x));
        }
    }

    /// <summary>
    /// Upper bound on the tip's distance from the axis of the joint driving row <paramref name="row"/>: that row's
    /// link length plus every later row's |a| + |d| (the row's own d runs along the axis).
    /// </summary>
    internal static double LeverBound(RobotDefinition robot, int row)
    {
        var bound = Math.Abs(robot.Dh[row].AMm);
        for (var r = row + 1; r < robot.Dh.Count; r++)
        {
            bound += Math.Abs(robot.Dh[r].AMm) + Math.Abs(robot.Dh[r].DMm);
        }

        return bound;
    }

    /// <summary>Upper bound on the tip's distance from the origin of the joint driving row <paramref name="row"/>.</summary>
    internal static double ReachBound(RobotDefinition robot, int row) => LeverBound(robot, row) + Math.Abs(robot.Dh[row].DMm);

    /// <summary>Evenly spaced values from min to max inclusive.</summary>
    private readonly record struct JointGrid(double Min, double Step, int Count)
    {
        public double At(int i) => Min + (i * Step);

        /// <summary>Steps small enough that a lever of <paramref name="lever"/> mm moves the tip under half a cell.</summary>
        public static JointGrid For(JointDefinition joint, double lever, double cellMm)
        {
            var span = joint.MaxRad - joint.MinRad;
            if (span <= 0 || lever <= 0)
            {
                return new JointGrid(joint.MinRad, 0, 1);
            }

            var count = (int)Math.Ceiling(span * lever / (0.5 * cellMm)) + 1;
            return new JointGrid(joint.MinRad, span / (count - 1), count);
        }
    }
}
