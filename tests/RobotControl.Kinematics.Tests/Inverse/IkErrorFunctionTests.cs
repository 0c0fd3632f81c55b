using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Kinematics.Tests.Inverse;

public sealed class IkErrorFunctionTests
{
    public static TheoryData<string, OrientationAxes> Cases => new()
    {
        { "lb-1.0.json", OrientationAxes.All },
        { "lb-1.0.json", OrientationAxes.X | OrientationAxes.Z },
        { "crb-1.0.json", OrientationAxes.Z },
        { "crb-1.0.json", OrientationAxes.None },
    };

    [Theory]
    [MemberData(nameof(Cases))]
    public void The_gradient_of_E_matches_central_finite_differences(string file, OrientationAxes axes)
    {
        var chain = new KinematicChain(TestRobots.ByFile(file));
        var solver = new IkSolver(chain, new IkOptions { PositionWeight = 3 }); // not 1, so a misplaced weight shows
        var random = new Random(17);
        var n = chain.JointCount;
        var gradient = new double[n];
        for (var s = 0; s < 20; s++)
        {
            var q = IkTestData.RandomJoints(chain, random);
            var target = new IkTarget(
                new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5) * 300,
                Rotation3d.FromRollPitchYaw(random.NextDouble() * 6, random.NextDouble() * 3, random.NextDouble() * 6),
                axes);
            solver.SpecGradient(target, q, gradient);
            for (var i = 0; i < n; i++)
            {
                const double h = 1e-6;
                var (plus, minus) = IkTestData.Nudged(q, i, h);
                var numeric = (solver.SpecError(target, plus) - solver.SpecError(target, minus)) / (2 * h);
                Assert.True(Math.Abs(numeric - gradient[i]) <= 1e-6 * (1 + Math.Abs(numeric)),
                    $"joint {i}: analytic {gradient[i]}, numeric {numeric}");
            }
        }
    }

    [Fact]
    public void E_is_the_weighted_sum_of_the_position_and_axis_terms()
    {
        var chain = new KinematicChain(TestRobots.Lb);
        var options = new IkOptions { PositionWeight = 2, OrientationWeight = 300 };
        var solver = new IkSolver(chain, options);
        double[] q = [-0.2, -0.4, 0.3, 1.1, 0.5];
        var state = chain.CreateState();
        state.Update(q);
        var rd = Rotation3d.FromRollPitchYaw(0.1, 0.2, 0.3);
        var target = new IkTarget(new Vector3d(10, 20, 30), rd, OrientationAxes.X | OrientationAxes.Z);
        var expected = (2 * (target.Position - state.ToolPosition).LengthSquared)
            + (300 * Math.Pow(Vector3d.Dot(rd.X, state.ToolRotation.X) - 1, 2))
            + (300 * Math.Pow(Vector3d.Dot(rd.Z, state.ToolRotation.Z) - 1, 2));
        Assert.Equal(expected, solver.SpecError(target, q), 9);
    }

    [Fact]
    public void The_CCD_step_is_the_best_angle_within_the_joint_range()
    {
        var random = new Random(2);
        for (var s = 0; s < 400; s++)
        {
            var k1 = (random.NextDouble() - 0.5) * 10;
            var k2 = (random.NextDouble() - 0.5) * 10;
            var k3 = (random.NextDouble() - 0.5) * 10;
            var min = -random.NextDouble() * 4;
            var max = random.NextDouble() * (s % 3 == 0 ? 8 : 3);
            var q = min + (random.NextDouble() * (max - min));
            var phi = CyclicCoordinateDescent.BestStep(k1, k2, k3, q, min, max);
            Assert.InRange(q + phi, min - 1e-12, max + 1e-12);
            var best = G(k1, k2, k3, phi);
            var scanned = double.NegativeInfinity;
            for (var k = 0; k <= 1000; k++)
            {
                scanned = Math.Max(scanned, G(k1, k2, k3, min + ((max - min) * k / 1000.0) - q));
            }

            Assert.True(scanned <= best + 1e-9, $"a scanned angle gives g = {scanned}, the step {phi} gives {best}");
        }
    }

    [Theory]
    [MemberData(nameof(Cases))]
    public void A_CCD_cycle_matches_a_cycle_that_recomputes_every_frame_and_never_raises_the_error(string file, OrientationAxes axes)
    {
        var chain = new KinematicChain(TestRobots.ByFile(file));
        var options = new IkOptions { PositionWeight = 3 }; // not 1, so a misplaced weight shows
        var solver = new IkSolver(chain, options);
        var problem = solver.Problem;
        var random = new Random(9);
        var state = chain.CreateState();
        for (var s = 0; s < 30; s++)
        {
            var target = IkTestData.TargetOf(chain, IkTestData.RandomJoints(chain, random), axes);
            var q = IkTestData.RandomJoints(chain, random);
            var reference = (double[])q.Clone();
            Assert.True(problem.SetTarget(target));
            var before = problem.Evaluate(q);
            var after = CyclicCoordinateDescent.Cycle(problem, q);
            Assert.True(after <= before + 1e-9);

            // The textbook cycle: frames recomputed after every joint, k1..k3 exactly as docs/algorithms.md writes them.
            for (var i = chain.JointCount - 1; i >= 0; i--)
            {
                state.Update(reference);
                var z = state.JointAxis(i);
                var pih = state.ToolPosition - state.JointOrigin(i);
                var pid = target.Position - state.JointOrigin(i);
                var k1 = options.PositionWeight * Vector3d.Dot(pid, z) * Vector3d.Dot(pih, z);
                var k2 = options.PositionWeight * Vector3d.Dot(pid, pih);
                var k3 = options.PositionWeight * Vector3d.Dot(z, Vector3d.Cross(pih, pid));
                for (var j = 0; j < 3; j++)
                {
                    if (((int)axes & (1 << j)) != 0)
                    {
                        var rh = state.ToolRotation[j];
                        var rd = target.Rotation[j];
                        k1 += options.OrientationWeight * Vector3d.Dot(rd, z) * Vector3d.Dot(rh, z);
                        k2 += options.OrientationWeight * Vector3d.Dot(rd, rh);
                        k3 += options.OrientationWeight * Vector3d.Dot(z, Vector3d.Cross(rh, rd));
                    }
                }

                reference[i] += CyclicCoordinateDescent.BestStep(k1, k2, k3, reference[i], chain.MinRad[i], chain.MaxRad[i]);
            }

            for (var i = 0; i < q.Length; i++)
            {
                Assert.True(Math.Abs(reference[i] - q[i]) <= 1e-9, $"sample {s} joint {i}: textbook {reference[i]}, ours {q[i]}");
            }
        }
    }

    private static double G(double k1, double k2, double k3, double phi) =>
        (k1 * (1 - Math.Cos(phi))) + (k2 * Math.Cos(phi)) + (k3 * Math.Sin(phi));
}
