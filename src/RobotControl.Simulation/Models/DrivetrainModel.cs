using RobotControl.Definitions.Model;

namespace RobotControl.Simulation.Models;

/// <summary>
/// One driven axis: a brushless DC motor (winding R-L circuit, back-EMF, torque constant, rotor inertia, static and
/// viscous friction, from the datasheet), its planetary gearhead and spur/bevel stages (ratio, efficiency, backlash
/// at the output) and the reflected load (link inertia and an external torque that can stall it). SI units inside.
/// </summary>
public sealed class DrivetrainModel
{
    private const double RpmToRadS = 2 * Math.PI / 60;
    private readonly double _resistance;
    private readonly double _inductance;
    private readonly double _torqueConstant;
    private readonly double _backEmfConstant;
    private readonly double _staticFriction;
    private readonly double _viscousFriction;
    private readonly double _inertia;
    private readonly double _backlash;

    /// <summary>Builds the model of <paramref name="actuator"/> with the datasheet of its motor.</summary>
    public DrivetrainModel(ActuatorDefinition actuator, MotorDefinition motor, double gearheadBacklashRad, double linkInertiaKgM2)
    {
        ArgumentNullException.ThrowIfNull(actuator);
        ArgumentNullException.ThrowIfNull(motor);
        Actuator = actuator;
        Motor = motor;
        Ratio = actuator.Drivetrain.TotalRatio;
        Efficiency = actuator.Drivetrain.TotalEfficiency;
        _resistance = motor.TerminalResistanceOhm;
        _inductance = motor.TerminalInductanceUH * 1e-6;
        _torqueConstant = motor.TorqueConstantMNmPerA * 1e-3;
        _backEmfConstant = motor.BackEmfConstantMVPerRpm * 1e-3 / RpmToRadS;
        // Moving, the motor loses at least its no-load current's torque (bearings, brushes of the Hall PCB, gear drag).
        _staticFriction = Math.Max(motor.StaticFrictionTorqueMNm, motor.NoLoadCurrentA * motor.TorqueConstantMNmPerA) * 1e-3;
        _viscousFriction = motor.DynamicFrictionMNmPerRpm * 1e-3 / RpmToRadS;
        _inertia = (motor.RotorInertiaGCm2 * 1e-7) + (linkInertiaKgM2 / (Ratio * Ratio));
        _backlash = gearheadBacklashRad / actuator.Drivetrain.StageRatio; // backlash is at the gearhead output
        SupplyVoltage = motor.NominalVoltageV;
    }

    /// <summary>The axis.</summary>
    public ActuatorDefinition Actuator { get; }

    /// <summary>The motor's datasheet.</summary>
    public MotorDefinition Motor { get; }

    /// <summary>Total reduction motor to output.</summary>
    public double Ratio { get; }

    /// <summary>Total efficiency of the gear train.</summary>
    public double Efficiency { get; }

    /// <summary>Bridge supply voltage (the motor's nominal voltage).</summary>
    public double SupplyVoltage { get; set; }

    /// <summary>Rotor angle, radians (motor side, unbounded).</summary>
    public double RotorAngle { get; private set; }

    /// <summary>Rotor speed, rad/s.</summary>
    public double RotorSpeed { get; private set; }

    /// <summary>Winding current, A (signed).</summary>
    public double Current { get; private set; }

    /// <summary>Output angle (the axis after the last stage), radians; lags the rotor by up to the backlash.</summary>
    public double OutputAngle { get; private set; }

    /// <summary>External torque at the output, N·m, that resists motion up to its magnitude (an obstacle; 0: none).</summary>
    public double ObstacleTorque { get; set; }

    /// <summary>Output limits (hard stops), radians.</summary>
    public (double Min, double Max) HardStops { get; set; } = (double.NegativeInfinity, double.PositiveInfinity);

    /// <summary>Places the axis at rest at <paramref name="outputAngle"/> (power-on state).</summary>
    public void Reset(double outputAngle)
    {
        OutputAngle = outputAngle;
        RotorAngle = outputAngle * Ratio;
        RotorSpeed = 0;
        Current = 0;
    }

    /// <summary>
    /// Advances by <paramref name="dt"/> seconds with the bridge applying <paramref name="duty"/> (-1..1) of the supply
    /// when <paramref name="enabled"/>; a disabled bridge lets the winding float (no current).
    /// </summary>
    public void Step(double duty, bool enabled, double dt)
    {
        // Electrical: L di/dt = V - R i - ke w, solved exactly over the step (tau_e is tens of microseconds).
        if (enabled)
        {
            var v = Math.Clamp(duty, -1, 1) * SupplyVoltage;
            var steady = (v - (_backEmfConstant * RotorSpeed)) / _resistance;
            Current = steady + ((Current - steady) * Math.Exp(-dt * _resistance / _inductance));
        }
        else
        {
            Current = 0;
        }

        // Mechanical, motor side: the obstacle and the gear losses act through the train.
        var drive = _torqueConstant * Current;
        var resist = _staticFriction + (ObstacleTorque / (Ratio * Efficiency));
        if (RotorSpeed == 0 && Math.Abs(drive) <= resist)
        {
            return; // held by static friction / the obstacle
        }

        var direction = RotorSpeed != 0 ? Math.Sign(RotorSpeed) : Math.Sign(drive);
        var net = drive - (direction * resist) - (_viscousFriction * RotorSpeed);
        var speed = RotorSpeed + (net / _inertia * dt);
        if (RotorSpeed != 0 && Math.Sign(speed) != Math.Sign(RotorSpeed) && Math.Abs(drive) <= resist)
        {
            speed = 0; // friction stops the rotor, it does not reverse it
        }

        RotorAngle += 0.5 * (RotorSpeed + speed) * dt;
        RotorSpeed = speed;

        // Output follows the rotor through the backlash gap and stops at the hard stops.
        var driven = RotorAngle / Ratio;
        if (driven - OutputAngle > _backlash / 2)
        {
            OutputAngle = driven - (_backlash / 2);
        }
        else if (OutputAngle - driven > _backlash / 2)
        {
            OutputAngle = driven + (_backlash / 2);
        }

        if (OutputAngle < HardStops.Min || OutputAngle > HardStops.Max)
        {
            OutputAngle = Math.Clamp(OutputAngle, HardStops.Min, HardStops.Max);
            RotorAngle = (OutputAngle + (Math.Sign(driven - OutputAngle) * _backlash / 2)) * Ratio;
            RotorSpeed = 0;
        }
    }
}
