using RobotControl.Definitions.Model;
using RobotControl.Modules;
using RobotControl.Simulation.Models;
using RobotControl.Simulation.Units;

namespace RobotControl.Simulation;

/// <summary>One simulated motor with its drivetrain, Hall sensors, current sense and pot: the truth a test compares against.</summary>
public sealed class VirtualAxis
{
    private int? _hallFailedCode;

    internal VirtualAxis(MotorConfig config, int moduleIndex, DrivetrainModel model, PotVariation potVariation)
    {
        Config = config;
        ModuleIndex = moduleIndex;
        Model = model;
        PotVariation = potVariation;
        TruePot = potVariation.Apply(config.Motor.Pot);
    }

    /// <summary>The motor as the robot file configures it.</summary>
    public MotorConfig Config { get; }

    /// <summary>
    /// The pot's true curve, which its readings follow: the robot file's design curve, or with unit variation
    /// (<see cref="VirtualRobotOptions.UnitVariationSeed"/>) this unit's own. A calibration is checked against it.
    /// </summary>
    public PotCalibration TruePot { get; }

    /// <summary>How <see cref="TruePot"/> differs from the design curve (<see cref="PotVariation.None"/> without unit variation).</summary>
    public PotVariation PotVariation { get; }

    /// <summary>Axis output angle, radians (the truth).</summary>
    public double OutputAngleRad => Model.OutputAngle;

    /// <summary>Winding current, A (signed; the truth, without sensor noise).</summary>
    public double CurrentA => Model.Current;

    /// <summary>PWM the firmware applies (-255..255).</summary>
    public int Pwm { get; internal set; }

    /// <summary>True while the firmware enables the bridge.</summary>
    public bool DriverEnabled { get; internal set; }

    /// <summary>
    /// External torque at the axis output (N·m) that resists motion up to its magnitude: an obstacle or a jammed
    /// joint. 0: none.
    /// </summary>
    public double ObstacleTorqueNm
    {
        get => Model.ObstacleTorque;
        set => Model.ObstacleTorque = Math.Abs(value);
    }

    /// <summary>
    /// Added to the current the module's sensor reads, A (a current spike or a failing sense resistor): the firmware
    /// and the host see it, the drivetrain does not. 0: none.
    /// </summary>
    public double CurrentSenseOffsetA { get; set; }

    /// <summary>
    /// A failed joint pot: its ADC reads this raw value whatever the joint does (0: an open wiper pulled to ground).
    /// Null: the pot follows the joint (with its non-linearity and noise).
    /// </summary>
    public int? PotFailedRaw { get; set; }

    /// <summary>
    /// A failed Hall connector or sensor: the module's three Hall lines read this fixed 3-bit code whatever the rotor
    /// does (7: the connector off, its pull-ups read 111; 0: the lines shorted to ground; 1..6 a stuck sensor). The
    /// firmware sees the change to it as one Hall edge (an invalid code latches its Hall error) and then no edges
    /// while it lasts. Null: the lines follow the rotor.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">Not a 3-bit code (0..7).</exception>
    public int? HallFailedCode
    {
        get => _hallFailedCode;
        set
        {
            if (value is < 0 or > 7)
            {
                throw new ArgumentOutOfRangeException(nameof(value), value, $"{Config.FullName}: a Hall code is 3 bits (0..7)");
            }

            _hallFailedCode = value;
        }
    }

    internal int ModuleIndex { get; }

    internal DrivetrainModel Model { get; }

    internal int LastSector { get; set; }

    internal MotorDefinition Motor => Model.Motor;
}
