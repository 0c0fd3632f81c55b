using MathNet.Numerics.LinearAlgebra;
using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Tests.Inverse;

namespace RobotControl.Kinematics.Tests.Forward;

/// <summary>Argument checks and the small helpers of the forward kinematics, each against hand-derived values.</summary>
public sealed class ForwardArgumentTests
{
    private static readonly JointDefinition[] TwoJoints =
    [
        new("first", "q0", -1.0, 0.5, "test"),
        new("second", "q1", 0.2, 1.4, "test"),
    ];

    // A planar two-link arm along x: 100 mm then 50 mm, both about z.
    private static readonly DhRow[] PlanarRows = [new(0, 100, 0, 0, 0), new(0, 50, 0, 0, 1)];

    [Fact]
    public void A_fixed_row_ignores_the_joint_angle()
    {
        // Rz(0.5) then a = 10 along the new x: the joint value passed must not change it.
        var t = DhMatrix.RowTransform(new DhRow(0, 10, 0, 0.5, -1), 1.0);
        Assert.Equal(Math.Cos(0.5), t[0, 0], 15);
        Assert.Equal(-Math.Sin(0.5), t[0, 1], 15);
        Assert.Equal(10 * Math.Cos(0.5), t[0, 3], 12);
        Assert.Equal(10 * Math.Sin(0.5), t[1, 3], 12);
    }

    [Fact]
    public void Tool_transform_needs_a_value_for_every_driven_row_but_none_for_fixed_rows()
    {
        var message = Assert.Throws<ArgumentException>(() => DhMatrix.ToolTransform(PlanarRows, [0.1])).Message;
        Assert.Contains("joint vector has 1 values; a DH row needs joint 1", message, StringComparison.Ordinal);

        // Only fixed rows: an empty joint vector is enough (d = 5 along z, then a = 7 along x).
        var t = DhMatrix.ToolTransform([new DhRow(0, 0, 5, 0, -1), new DhRow(0, 7, 0, 0, -1)], []);
        Assert.Equal(7, t[0, 3], 15);
        Assert.Equal(5, t[2, 3], 15);
    }

    [Fact]
    public void Null_arguments_are_refused_by_name()
    {
        Assert.Throws<ArgumentNullException>(() => DhMatrix.RowTransform(null!, 0));
        Assert.Throws<ArgumentNullException>(() => DhMatrix.ToolTransform((IReadOnlyList<DhRow>)null!, []));
        Assert.Throws<ArgumentNullException>(() => DhMatrix.ToolTransform((KinematicChain)null!, []));
        Assert.Throws<ArgumentNullException>(() => DhMatrix.ToPose(null!));
        Assert.Throws<ArgumentNullException>(() => new KinematicChain(null!, TwoJoints));
        Assert.Throws<ArgumentNullException>(() => new KinematicChain(PlanarRows, null!));
        Assert.Throws<ArgumentNullException>(() => Manipulability.Of(null!));
        Assert.Throws<ArgumentNullException>(() => Manipulability.Of(null!, [0]));
    }

    [Fact]
    public void To_pose_takes_only_a_4_x_4_matrix()
    {
        Assert.Throws<ArgumentException>(() => DhMatrix.ToPose(Matrix<double>.Build.Dense(3, 4)));
        Assert.Throws<ArgumentException>(() => DhMatrix.ToPose(Matrix<double>.Build.Dense(4, 3)));
        var pose = DhMatrix.ToPose(DhMatrix.Translation(1, 2, 3));
        Assert.Equal(new Vector3d(1, 2, 3), pose.Position);
    }

    [Fact]
    public void A_chain_refuses_no_rows_a_row_naming_a_missing_joint_and_a_joint_without_a_row()
    {
        var empty = Assert.Throws<ArgumentException>(() => new KinematicChain([], TwoJoints));
        Assert.Contains("a chain needs at least one DH row", empty.Message, StringComparison.Ordinal);
        var beyond = Assert.Throws<ArgumentException>(() => new KinematicChain([new DhRow(0, 1, 0, 0, 0), new DhRow(0, 1, 0, 0, 2)], TwoJoints));
        Assert.Contains("DH row 1 names joint 2 of 2", beyond.Message, StringComparison.Ordinal);
        var undriven = Assert.Throws<ArgumentException>(() => new KinematicChain([new DhRow(0, 1, 0, 0, 0), new DhRow(0, 1, 0, 0, -1)], TwoJoints));
        Assert.Contains("every joint must drive a DH row", undriven.Message, StringComparison.Ordinal);
        var chain = new KinematicChain(PlanarRows, TwoJoints);
        Assert.Equal(0, chain.RowOfJoint(0));
        Assert.Equal(1, chain.RowOfJoint(1));
    }

    [Fact]
    public void Within_limits_checks_each_joint_against_both_ends_with_the_tolerance()
    {
        var chain = new KinematicChain(PlanarRows, TwoJoints);
        Assert.True(chain.WithinLimits([-1.0, 1.4]));
        Assert.False(chain.WithinLimits([-1.01, 1.0]));
        Assert.False(chain.WithinLimits([0.0, 1.41]));
        Assert.False(chain.WithinLimits([0.0, 0.1]));
        Assert.True(chain.WithinLimits([0.0, 0.1], tolerance: 0.11));
        Assert.False(chain.WithinLimits([0.0, 0.1], tolerance: 0.09));
        Assert.True(chain.WithinLimits([0.0, 1.45], tolerance: 0.06));
        Assert.False(chain.WithinLimits([0.0, 1.45], tolerance: 0.04));
    }

    [Fact]
    public void Mid_range_is_halfway_between_the_limits()
    {
        var chain = new KinematicChain(PlanarRows, TwoJoints);
        var q = new double[2];
        chain.MidRange(q);
        Assert.Equal(-0.25, q[0], 15);
        Assert.Equal(0.8, q[1], 15);
    }

    [Fact]
    public void State_and_Jacobian_refuse_short_spans_and_take_exact_ones()
    {
        var state = new KinematicChain(PlanarRows, TwoJoints).CreateState();
        var tooFew = Assert.Throws<ArgumentException>(() => state.Update([0.1]));
        Assert.Contains("joint vector has 1 values; the chain has 2 joints", tooFew.Message, StringComparison.Ordinal);
        state.Update([0.0, Math.PI / 2]);
        Assert.Equal(new Vector3d(100, 50, 0), state.ToolPosition, (a, b) => (a - b).Length < 1e-12);

        Assert.Throws<ArgumentException>(() => state.Jacobian(new double[11]));
        var jacobian = new double[12];
        state.Jacobian(jacobian);
        // Column 0 (about z at the origin): z x (100, 50, 0) = (-50, 100, 0); column 1 (about z at (100, 0, 0)): (-50, 0, 0).
        Assert.Equal(-50, jacobian[0], 12);
        Assert.Equal(-50, jacobian[1], 12);
        Assert.Equal(100, jacobian[2], 12);
        Assert.Equal(0, jacobian[3], 12);
        Assert.Equal(1, jacobian[10], 15);
        Assert.Equal(1, jacobian[11], 15);
    }

    [Fact]
    public void Manipulability_from_a_Jacobian_checks_its_columns_and_length()
    {
        Assert.Throws<ArgumentOutOfRangeException>(() => Manipulability.FromJacobian(new double[9], 0));
        Assert.Throws<ArgumentException>(() => Manipulability.FromJacobian(new double[8], 3));
        // Exactly 3 x 3 values: the identity rows give w = sqrt(det(I)) = 1; 2 * identity gives sqrt(det(4 I)) = 8.
        Assert.Equal(1, Manipulability.FromJacobian([1, 0, 0, 0, 1, 0, 0, 0, 1], 3), 15);
        Assert.Equal(8, Manipulability.FromJacobian([2, 0, 0, 0, 2, 0, 0, 0, 2], 3), 15);
    }

    [Fact]
    public void Manipulability_of_a_joint_subset_matches_a_finite_difference_Jacobian()
    {
        // The PUMA-like chain: the axes of joints 2, 3 and 5 do not pass through the base origin.
        var chain = IkTestData.Puma();
        var state = chain.CreateState();
        double[] q = [0.3, -0.4, 0.2, 0.9, 0.5, 0.1];
        int[] subset = [1, 2, 4];
        const double h = 1e-6;
        var columns = new Vector3d[3];
        for (var c = 0; c < 3; c++)
        {
            var (plus, minus) = IkTestData.Nudged(q, subset[c], h);
            state.Update(plus);
            var p = state.ToolPosition;
            state.Update(minus);
            columns[c] = (p - state.ToolPosition) / (2 * h);
        }

        // w = sqrt(det(J Jᵀ)) = |det J| for a square 3 x 3 J: the triple product of its columns.
        var expected = Math.Abs(Vector3d.Dot(columns[0], Vector3d.Cross(columns[1], columns[2])));
        state.Update(q);
        var w = Manipulability.Of(state, subset);
        Assert.True(expected > 1, $"the test pose is near a singularity (w = {expected})");
        Assert.Equal(expected, w, 1e-6 * expected);
    }
}
