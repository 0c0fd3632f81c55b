namespace RobotControl.Robot.Bus;

/// <summary>
/// "Start from where the motors are": taken when the motors go on (<see cref="Take"/>, set-up on the bus thread): from
/// then until the control loop publishes newer setpoints for an arm, that arm's goals are its measured positions, so
/// nothing moves until the loop or a manual command says so. The setpoints themselves are never written here (the
/// loop's thread alone writes them); the loop side follows <see cref="Generation"/> to take the measured positions as
/// its last setpoints.
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class GoalSeed
{
    private readonly int[] _jointVersion; // per arm: the setpoint writes the seed replaces (-1: no seed)
    private readonly int[] _jawVersion;
    private readonly double[][] _joints;
    private readonly double[] _jaws;
    private volatile int _generation;

    public GoalSeed(RobotLayout layout)
    {
        _jointVersion = [.. Enumerable.Repeat(-1, layout.ArmCount)];
        _jawVersion = [.. Enumerable.Repeat(-1, layout.ArmCount)];
        _joints = [.. Enumerable.Range(0, layout.ArmCount).Select(_ => new double[layout.JointCount])];
        _jaws = new double[layout.ArmCount];
    }

    /// <summary>How many seeds were taken (the loop side watches it).</summary>
    public int Generation => _generation;

    /// <summary>Seeds the goals from the measured positions, replacing the setpoints published so far (bus thread).</summary>
    public void Take(SetpointExchange setpoints, FeedbackExchange feedback, RobotLayout layout)
    {
        for (var arm = 0; arm < layout.ArmCount; arm++)
        {
            feedback.ReadJoints(arm, _joints[arm]);
            _jaws[arm] = layout.ToolMotor(arm)?.PositionRad ?? 0;
            _jointVersion[arm] = setpoints.JointVersion(arm);
            _jawVersion[arm] = setpoints.JawVersion(arm);
        }

        _generation++;
    }
    /// <summary>The arm's joint setpoints, or the seed while the loop has published nothing newer (bus thread).</summary>
    public void Joints(SetpointExchange setpoints, int arm, Span<double> q)
    {
        if (setpoints.ReadJoints(arm, q) == _jointVersion[arm])
        {
            _joints[arm].CopyTo(q);
        }
    }

    /// <summary>The arm's jaw setpoint, or the seed while the loop has published nothing newer (bus thread).</summary>
    public double Jaw(SetpointExchange setpoints, int arm, Span<double> jaw)
    {
        return setpoints.ReadJaw(arm, jaw) == _jawVersion[arm] ? _jaws[arm] : jaw[0];
    }
}
