using RobotControl.Robot.Control;

namespace RobotControl.Robot.Bus;

/// <summary>The control loop's side: <see cref="IRobotPort"/>.</summary>
public sealed partial class BusRobot
{
    /// <inheritdoc />
    public void WriteJointSetpoints(int arm, ReadOnlySpan<double> jointsRad)
    {
        var n = Definition.JointCount;
        if ((uint)arm >= (uint)ArmCount || jointsRad.Length < n)
        {
            SetLatched(RobotFaults.SetpointRejected);
            return;
        }

        Span<double> q = stackalloc double[n];
        var last = _lastJointSetpoint[arm];
        var rejected = false;
        for (var j = 0; j < n; j++)
        {
            var v = jointsRad[j];
            if (!double.IsFinite(v))
            {
                rejected = true;
                q[j] = last[j];
                continue;
            }

            var joint = Definition.Joints[j];
            q[j] = Math.Clamp(v, joint.MinRad, joint.MaxRad);
        }

        if (rejected)
        {
            SetLatched(RobotFaults.SetpointRejected);
        }

        q.CopyTo(last);
        _jointSetpoints[arm].Write(q);
    }

    /// <inheritdoc />
    public void WriteJawSetpoint(int arm, double jawRad)
    {
        if ((uint)arm >= (uint)ArmCount || !double.IsFinite(jawRad))
        {
            SetLatched(RobotFaults.SetpointRejected);
            return;
        }

        Span<double> jaw = [Math.Clamp(jawRad, _map.JawMinRad, _map.JawMaxRad)];
        _jawSetpoints[arm].Write(jaw);
    }

    /// <inheritdoc />
    public void ReadJointPositions(int arm, Span<double> jointsRad) => _jointPositions[arm].Read(jointsRad);

    /// <inheritdoc />
    public void ReadMotorCurrents(int arm, Span<double> currentsA) => _currents[arm].Read(currentsA);

    /// <inheritdoc />
    public void HoldPosition()
    {
        Span<double> q = stackalloc double[Definition.JointCount];
        for (var arm = 0; arm < ArmCount; arm++)
        {
            _jointPositions[arm].Read(q);
            q.CopyTo(_lastJointSetpoint[arm]);
            _jointSetpoints[arm].Write(q);
            if (_toolActuator >= 0 && _motorOf[arm][_toolActuator] is { } tool)
            {
                Span<double> jaw = [tool.PositionRad];
                _jawSetpoints[arm].Write(jaw);
            }
        }

        foreach (var m in _motors)
        {
            if (m.IsManual)
            {
                m.SetSetpoint(m.PositionRad);
            }
        }
    }

    /// <inheritdoc />
    public void Dispose()
    {
        Stop();
        _client.Dispose();
    }
}
