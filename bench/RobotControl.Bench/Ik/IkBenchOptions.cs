using System.Globalization;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Bench.Ik;

/// <summary>Command-line options of the ik benchmark.</summary>
internal sealed record IkBenchOptions(
    string Robot,
    int Samples,
    ulong Seed,
    string? Json,
    int BaselineSamples,
    int TrackingSteps,
    OrientationAxes? Axes,
    bool Kdl,
    int Repeat,
    IReadOnlyList<string> Sets,
    int SpecialSamples,
    int Worst,
    string? Replay)
{
    /// <summary>The target sets beside the uniform one (IkSpecialSets).</summary>
    public static readonly string[] SpecialSetNames = ["near_singular", "at_limits", "near_boundary"];

    public static IkBenchOptions? Parse(string[] args)
    {
        string? robot = null;
        string? json = null;
        var samples = 10_000;
        ulong seed = 1;
        int? baseline = null;
        var tracking = 10_000;
        OrientationAxes? axes = null;
        var kdl = true;
        var noBaseline = false;
        var repeat = 3;
        string[] sets = ["random", .. SpecialSetNames];
        int? special = null;
        var worst = 10;
        string? replay = null;
        for (var i = 0; i < args.Length; i++)
        {
            string Next() => i + 1 < args.Length ? args[++i] : throw new ArgumentException($"{args[i]} needs a value");
            int Int()
            {
                var option = args[i];
                var text = Next();
                return int.TryParse(text, NumberStyles.Integer, CultureInfo.InvariantCulture, out var value)
                    ? value
                    : throw new ArgumentException($"{option}: '{text}' is not a whole number");
            }

            switch (args[i])
            {
                case "--robot": robot = Next(); break;
                case "--samples": samples = Int(); break;
                case "--seed":
                    var seedText = Next();
                    seed = ulong.TryParse(seedText, NumberStyles.Integer, CultureInfo.InvariantCulture, out var parsed)
                        ? parsed
                        : throw new ArgumentException($"--seed: '{seedText}' is not a whole number");
                    break;
                case "--json": json = Next(); break;
                case "--baseline-samples": baseline = Int(); break;
                case "--tracking-steps": tracking = Int(); break;
                case "--axes":
                    axes = Next() switch
                    {
                        "all" => OrientationAxes.All,
                        "z" => OrientationAxes.Z,
                        "none" => OrientationAxes.None,
                        var other => throw new ArgumentException($"unknown --axes {other}"),
                    };
                    break;
                case "--no-kdl": kdl = false; break;
                case "--no-baseline": noBaseline = true; break;
                case "--repeat": repeat = Int(); break;
                case "--sets":
                    sets = Next().Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);
                    if (sets.FirstOrDefault(x => x != "random" && !SpecialSetNames.Contains(x)) is { } unknown)
                    {
                        throw new ArgumentException($"unknown --sets entry {unknown}: random, {string.Join(", ", SpecialSetNames)}");
                    }

                    break;
                case "--special-samples": special = Int(); break;
                case "--worst": worst = Int(); break;
                case "--replay": replay = Next(); break;
                default: return null;
            }
        }

        if (replay is not null)
        {
            return new IkBenchOptions(robot ?? "", 0, seed, json, 0, 2, axes, false, Math.Max(repeat, 1), [], 0, worst, replay);
        }

        if (robot is null || samples < 1)
        {
            return null;
        }

        // The baseline runs up to 15,000 CCD cycles per target; by default it gets the first 1,000 targets.
        var baselineSamples = noBaseline ? 0 : baseline ?? Math.Min(samples, 1_000);
        return new IkBenchOptions(robot, samples, seed, json, baselineSamples, Math.Max(tracking, 2), axes, kdl, Math.Max(repeat, 1),
            sets, Math.Max(special ?? Math.Min(samples, 100_000), 1), Math.Max(worst, 0), null);
    }
}
