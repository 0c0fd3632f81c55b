using RobotControl.Kinematics.Inverse;

namespace RobotControl.Bench.Ik;

/// <summary>One run of our solver over a target set: the statistics and, target by target, what the report names.</summary>
/// <param name="Set">The targets.</param>
/// <param name="Stats">Solve rate and wall-time statistics.</param>
/// <param name="BytesPerSolve">Bytes allocated per solve in the timed passes.</param>
/// <param name="TimesUs">Wall time per target, the fastest of the repeated passes.</param>
/// <param name="CpuUs">Thread CPU time per target, one further pass.</param>
/// <param name="Iterations">Iterations the solver reported per target.</param>
/// <param name="Solved">Whether the answer passed the check, per target.</param>
/// <param name="Status">The solver's status per target.</param>
internal sealed record OurRandomRun(
    IkTargetSet Set,
    SolverStats Stats,
    double BytesPerSolve,
    double[] TimesUs,
    double[] CpuUs,
    int[] Iterations,
    bool[] Solved,
    IkStatus[] Status);
