using System.Text.Json.Serialization;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Bench.Ik;

/// <summary>
/// One target the report names (a failure or one of the slowest), with everything needed to solve it again
/// (<c>ik --replay</c>): the pose, the axes that count, the seed the solver started from, and the joints the target was
/// made from. Angles in radians, written in round-trip precision.
/// </summary>
internal sealed record IkCase
{
    [JsonPropertyName("set")]
    public required string Set { get; init; }

    [JsonPropertyName("index")]
    public required int Index { get; init; }

    [JsonPropertyName("position_mm")]
    public required double[] PositionMm { get; init; }

    /// <summary>The target rotation's columns (tool x, y, z axes), each [x, y, z].</summary>
    [JsonPropertyName("rotation_columns")]
    public required double[][] RotationColumns { get; init; }

    [JsonPropertyName("axes")]
    public required string Axes { get; init; }

    [JsonPropertyName("seed_rad")]
    public required double[] SeedRad { get; init; }

    [JsonPropertyName("made_from_rad")]
    public required double[] MadeFromRad { get; init; }

    [JsonPropertyName("made_from_deg")]
    public double[] MadeFromDeg => MadeFromRad.Select(r => Math.Round(r * 180 / Math.PI, 4)).ToArray();

    [JsonPropertyName("status")]
    public required string Status { get; init; }

    [JsonPropertyName("solved")]
    public required bool Solved { get; init; }

    [JsonPropertyName("iterations")]
    public required int Iterations { get; init; }

    [JsonPropertyName("wall_us")]
    public required double WallUs { get; init; }

    [JsonPropertyName("cpu_us")]
    public required double CpuUs { get; init; }

    public IkTarget Target() => new(
        new Vector3d(PositionMm[0], PositionMm[1], PositionMm[2]),
        new Rotation3d(Column(0), Column(1), Column(2)),
        Enum.Parse<OrientationAxes>(Axes));

    public static IkCase From(OurRandomRun run, int index, double[] seed)
    {
        var target = run.Set.Targets[index];
        var p = target.Position;
        return new IkCase
        {
            Set = run.Set.Name,
            Index = index,
            PositionMm = [p.X, p.Y, p.Z],
            RotationColumns = [Array(target.Rotation.X), Array(target.Rotation.Y), Array(target.Rotation.Z)],
            Axes = target.AxisMask.ToString(),
            SeedRad = seed,
            MadeFromRad = run.Set.Joints[index],
            Status = run.Status[index].ToString(),
            Solved = run.Solved[index],
            Iterations = run.Iterations[index],
            WallUs = run.TimesUs[index],
            CpuUs = run.CpuUs[index],
        };
    }

    private Vector3d Column(int c) => new(RotationColumns[c][0], RotationColumns[c][1], RotationColumns[c][2]);

    private static double[] Array(Vector3d v) => [v.X, v.Y, v.Z];
}
