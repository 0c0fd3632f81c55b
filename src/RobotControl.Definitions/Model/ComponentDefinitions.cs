namespace RobotControl.Definitions.Model;

/// <summary>A brushless DC motor from the datasheet (SI-adjacent units as named).</summary>
public sealed record MotorDefinition(
    string Model,
    int PolePairs,
    double NominalVoltageV,
    double TerminalResistanceOhm,
    double NoLoadSpeedRpm,
    double NoLoadCurrentA,
    double StallTorqueMNm,
    double StaticFrictionTorqueMNm,
    double DynamicFrictionMNmPerRpm,
    double SpeedConstantRpmPerV,
    double BackEmfConstantMVPerRpm,
    double TorqueConstantMNmPerA,
    double TerminalInductanceUH,
    double MechanicalTimeConstantMs,
    double RotorInertiaGCm2,
    double RatedTorqueMNm,
    double RatedCurrentA,
    double RatedSpeedRpm,
    double MaxSpeedRpm,
    double MassG,
    double MaxWindingTemperatureC,
    double ThermalResistanceWindingHousingKPerW,
    double ThermalResistanceHousingAmbientKPerW,
    double ThermalTimeConstantWindingS,
    double ThermalTimeConstantHousingS);

/// <summary>A planetary gearhead series.</summary>
public sealed record GearheadDefinition(
    string Series,
    string ForMotor,
    double ContinuousOutputTorqueMNm,
    double IntermittentOutputTorqueMNm,
    double MaxInputSpeedRpm,
    double BacklashDeg,
    IReadOnlyList<GearheadStage> Stages);

/// <summary>One available reduction of a gearhead series.</summary>
public sealed record GearheadStage(double Ratio, double Efficiency);
