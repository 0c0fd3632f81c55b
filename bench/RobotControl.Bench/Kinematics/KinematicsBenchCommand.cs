using System.Diagnostics;
using System.Globalization;
using System.Text.Json;
using RobotControl.Definitions.Loading;
using RobotControl.Kinematics.ClosedForm;
using RobotControl.Kinematics.Coupling;
using RobotControl.Kinematics.Forward;

namespace RobotControl.Bench.Kinematics;

/// <summary>
/// <c>kinematics [--robots-dir hardware/robots] [--calls N] [--repeats R] [--json file]</c>: per-call cost (median over
/// R runs of N calls, ns) of the forward recursion, Jacobian, manipulability, joint -> motor -> joint mapping, the CRB
/// closed-form IK and the MathNet DH-matrix product it is checked against, for both robots, side by side in one run.
/// </summary>
internal sealed class KinematicsBenchCommand : IBenchCommand
{
    private static readonly JsonSerializerOptions JsonOptions = new() { WriteIndented = true };

    public string Name => "kinematics";

    public string Description => "forward kinematics, Jacobian, manipulability, coupling, CRB closed-form IK: ns per call";

    public int Run(string[] args)
    {
        var robotsDir = Option(args, "--robots-dir") ?? Path.Combine("hardware", "robots");
        var calls = int.Parse(Option(args, "--calls") ?? "200000", CultureInfo.InvariantCulture);
        var repeats = int.Parse(Option(args, "--repeats") ?? "7", CultureInfo.InvariantCulture);
        var json = Option(args, "--json");
        var results = new List<Dictionary<string, object>>();
        foreach (var file in new[] { "crb-1.0.json", "lb-1.0.json" })
        {
            var robot = RobotLoader.Load(Path.Combine(robotsDir, file));
            var chain = new KinematicChain(robot);
            var state = chain.CreateState();
            var n = chain.JointCount;
            var q = robot.Joints.Select(j => j.MidRad).ToArray();
            var jacobian = new double[6 * n];
            var motors = new double[n];
            var back = new double[n];
            var map = new JointMotorMap(robot);
            state.Update(q);
            var target = state.ToolPosition;
            CrbPositionIk? ik = robot.Name.StartsWith("CRB", StringComparison.Ordinal) ? new CrbPositionIk(robot) : null;
            var sink = 0.0;

            void Measure(string name, int count, Action body)
            {
                var ns = new double[repeats];
                body(); // warm-up
                for (var r = 0; r < repeats; r++)
                {
                    var watch = Stopwatch.StartNew();
                    for (var i = 0; i < count; i++)
                    {
                        body();
                    }

                    ns[r] = watch.Elapsed.TotalNanoseconds / count;
                }

                Array.Sort(ns);
                var median = ns[repeats / 2];
                Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{robot.Name,-8} {name,-34} {median,10:F1} ns/call"));
                results.Add(new Dictionary<string, object> { ["robot"] = robot.Name, ["operation"] = name, ["median_ns"] = Math.Round(median, 1), ["calls"] = count, ["repeats"] = repeats });
            }

            Measure("forward recursion (Update)", calls, () => { q[0] += 1e-9; state.Update(q); sink += state.ToolPosition.X; });
            Measure("Update + 6xn Jacobian", calls, () => { q[0] += 1e-9; state.Update(q); state.Jacobian(jacobian); sink += jacobian[0]; });
            Measure("manipulability (from state)", calls, () => sink += Manipulability.Of(state));
            Measure("joints -> motors -> joints", calls, () => { map.JointsToMotors(q, motors); map.MotorsToJoints(motors, back); sink += back[0]; });
            if (ik is not null)
            {
                Measure("CRB closed-form position IK", calls, () => { ik.Solve(target, back); sink += back[0]; });
            }

            Measure("DH matrix product (MathNet, allocates)", Math.Max(1, calls / 20), () => sink += DhMatrix.ToolTransform(chain, q)[0, 3]);
            GC.KeepAlive(sink);
        }

        if (json is not null)
        {
            File.WriteAllText(json, JsonSerializer.Serialize(results, JsonOptions));
        }

        return 0;
    }

    private static string? Option(string[] args, string name)
    {
        var i = Array.IndexOf(args, name);
        return i >= 0 && i + 1 < args.Length ? args[i + 1] : null;
    }
}
