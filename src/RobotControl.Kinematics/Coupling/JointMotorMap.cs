using MathNet.Numerics.LinearAlgebra;
using RobotControl.Definitions.Model;

namespace RobotControl.Kinematics.Coupling;

/// <summary>
/// Joint &lt;-&gt; motor mapping of one arm from the robot file's coupling coefficients (docs/robots.md): the output side of
/// kinematic actuator k turns a_k = Σ_j C[k, j] q_j (e.g. the upper sun gear of a differential shoulder turns
/// phi1 + phi2), and its motor shaft turns a_k times the drivetrain's total reduction (tau · tau_m). The inverse of C is
/// computed once with MathNet at construction; every mapping after that is allocation-free. Angles in radians; the
/// same linear maps hold for velocities. Torques map by the transpose (power is conserved):
/// joint torque = Cᵀ · actuator torque.
/// <para>
/// The tool's open/close drive is an actuator with no kinematic joint: it is mapped on its own (<see cref="JawToMotor"/>,
/// <see cref="MotorToJaw"/>). The jaw linkage's dimensions are not given by the design, so the drive's output angle
/// stands for the jaw angle (unit coefficient); the lead screw and links lie beyond this map.
/// </para>
/// Vectors of actuators and motors follow <see cref="Actuators"/> (the file order of the kinematic actuators).
/// Immutable and thread-safe.
/// </summary>
public sealed class JointMotorMap
{
    private readonly double[] _coupling;
    private readonly double[] _inverse;
    private readonly double[] _ratio;

    /// <summary>Builds the map of <paramref name="robot"/>.</summary>
    /// <exception cref="ArgumentException">
    /// The kinematic actuators do not number the joints, or their coupling matrix is singular (no inverse map).
    /// </exception>
    public JointMotorMap(RobotDefinition robot)
    {
        ArgumentNullException.ThrowIfNull(robot);
        var n = robot.JointCount;
        var kinematic = robot.Actuators.Where(a => a.IsKinematic).ToArray();
        if (kinematic.Length != n)
        {
            throw new ArgumentException($"{robot.Name}: {kinematic.Length} kinematic actuators for {n} joints; the map needs one per joint", nameof(robot));
        }

        var c = Matrix<double>.Build.Dense(n, n);
        for (var k = 0; k < n; k++)
        {
            if (kinematic[k].Coupling.Count != n)
            {
                throw new ArgumentException($"{robot.Name}: actuator {kinematic[k].Name} has {kinematic[k].Coupling.Count} coupling coefficients for {n} joints", nameof(robot));
            }

            for (var j = 0; j < n; j++)
            {
                c[k, j] = kinematic[k].Coupling[j];
            }
        }

        // A near-singular C would turn motor noise into huge joint errors: refuse it rather than invert it.
        var conditionNumber = c.ConditionNumber();
        if (!(conditionNumber < 1e8))
        {
            throw new ArgumentException($"{robot.Name}: the coupling matrix of the kinematic actuators is singular (condition number {conditionNumber:G3})", nameof(robot));
        }

        var inverse = c.Inverse();
        JointCount = n;
        Actuators = kinematic;
        _coupling = c.ToRowMajorArray();
        _inverse = inverse.ToRowMajorArray();
        _ratio = kinematic.Select(a => a.Drivetrain.TotalRatio).ToArray();
        ToolActuator = robot.Actuators.FirstOrDefault(a => !a.IsKinematic);
        JawMinRad = robot.Tool.JawMinRad;
        JawMaxRad = robot.Tool.JawMaxRad;
    }

    /// <summary>Number of joints, which is also the number of kinematic actuators.</summary>
    public int JointCount { get; }

    /// <summary>The kinematic actuators, in the order of actuator and motor vectors.</summary>
    public IReadOnlyList<ActuatorDefinition> Actuators { get; }

    /// <summary>The tool's open/close drive, or null when the robot has none.</summary>
    public ActuatorDefinition? ToolActuator { get; }

    /// <summary>Smallest jaw angle, radians.</summary>
    public double JawMinRad { get; }

    /// <summary>Largest jaw angle, radians.</summary>
    public double JawMaxRad { get; }

    /// <summary>C[actuator, joint], the coupling coefficient.</summary>
    public double Coefficient(int actuator, int joint) => _coupling[(actuator * JointCount) + joint];

    /// <summary>C⁻¹[joint, actuator].</summary>
    public double InverseCoefficient(int joint, int actuator) => _inverse[(joint * JointCount) + actuator];

    /// <summary>Total reduction motor -> actuator output of kinematic actuator <paramref name="actuator"/>.</summary>
    public double Ratio(int actuator) => _ratio[actuator];

    /// <summary>Index of the kinematic actuator named <paramref name="name"/>, or -1.</summary>
    public int IndexOfActuator(string name)
    {
        for (var k = 0; k < Actuators.Count; k++)
        {
            if (Actuators[k].Name == name)
            {
                return k;
            }
        }

        return -1;
    }

    /// <summary>Output-side actuator angles a = C q.</summary>
    public void JointsToActuators(ReadOnlySpan<double> joints, Span<double> actuators)
    {
        Check(joints, actuators);
        Multiply(_coupling, joints, actuators, transpose: false);
    }

    /// <summary>Joint angles q = C⁻¹ a from output-side actuator angles.</summary>
    public void ActuatorsToJoints(ReadOnlySpan<double> actuators, Span<double> joints)
    {
        Check(actuators, joints);
        Multiply(_inverse, actuators, joints, transpose: false);
    }

    /// <summary>Motor shaft angles m_k = ratio_k (C q)_k.</summary>
    public void JointsToMotors(ReadOnlySpan<double> joints, Span<double> motors)
    {
        JointsToActuators(joints, motors);
        for (var k = 0; k < JointCount; k++)
        {
            motors[k] *= _ratio[k];
        }
    }

    /// <summary>Joint angles from motor shaft angles: q = C⁻¹ (m / ratio).</summary>
    public void MotorsToJoints(ReadOnlySpan<double> motors, Span<double> joints)
    {
        Check(motors, joints);
        var n = JointCount;
        for (var j = 0; j < n; j++)
        {
            var sum = 0.0;
            for (var k = 0; k < n; k++)
            {
                sum += _inverse[(j * n) + k] * (motors[k] / _ratio[k]);
            }

            joints[j] = sum;
        }
    }

    /// <summary>Joint torques held by output-side actuator torques: τ_q = Cᵀ τ_a.</summary>
    public void ActuatorTorquesToJointTorques(ReadOnlySpan<double> actuatorTorques, Span<double> jointTorques)
    {
        Check(actuatorTorques, jointTorques);
        Multiply(_coupling, actuatorTorques, jointTorques, transpose: true);
    }

    /// <summary>Output-side actuator torques that hold joint torques: τ_a = C⁻ᵀ τ_q.</summary>
    public void JointTorquesToActuatorTorques(ReadOnlySpan<double> jointTorques, Span<double> actuatorTorques)
    {
        Check(jointTorques, actuatorTorques);
        Multiply(_inverse, jointTorques, actuatorTorques, transpose: true);
    }

    /// <summary>Motor shaft angle of the tool drive for jaw angle <paramref name="jawRad"/>.</summary>
    /// <exception cref="InvalidOperationException">The robot has no tool drive.</exception>
    public double JawToMotor(double jawRad) => jawRad * ToolRatio();

    /// <summary>Jaw angle for the tool drive's motor shaft angle <paramref name="motorRad"/>.</summary>
    /// <exception cref="InvalidOperationException">The robot has no tool drive.</exception>
    public double MotorToJaw(double motorRad) => motorRad / ToolRatio();

    private double ToolRatio() =>
        ToolActuator?.Drivetrain.TotalRatio ?? throw new InvalidOperationException("the robot has no tool open/close drive");

    private void Multiply(double[] matrix, ReadOnlySpan<double> input, Span<double> output, bool transpose)
    {
        var n = JointCount;
        for (var r = 0; r < n; r++)
        {
            var sum = 0.0;
            for (var c = 0; c < n; c++)
            {
                sum += (transpose ? matrix[(c * n) + r] : matrix[(r * n) + c]) * input[c];
            }

            output[r] = sum;
        }
    }

    private void Check(ReadOnlySpan<double> input, Span<double> output)
    {
        if (input.Length < JointCount || output.Length < JointCount)
        {
            throw new ArgumentException($"vectors need {JointCount} values (found {input.Length} in, room for {output.Length} out)");
        }

        if (input.Overlaps(output))
        {
            throw new ArgumentException("input and output must not overlap");
        }
    }
}
