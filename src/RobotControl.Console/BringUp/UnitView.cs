using RobotControl.Modules;
using RobotControl.Robot.Commissioning;

namespace RobotControl.WebConsole.BringUp;

/// <summary>The unit as its unit file has it, module by module of the robot file (the bring-up page's table).</summary>
/// <param name="Unit">The unit's name.</param>
/// <param name="File">Its unit file.</param>
/// <param name="Date">When it was last written, or null (no file yet).</param>
/// <param name="Error">The unit file's problem in one line (it does not read), or null.</param>
/// <param name="Modules">Every module of the robot file.</param>
public sealed record UnitView(string Unit, string File, string? Date, string? Error, IReadOnlyList<UnitModuleView> Modules)
{
    /// <summary>Reads <paramref name="setup"/>'s unit file now.</summary>
    public static UnitView Read(BringUpSetup setup)
    {
        ArgumentNullException.ThrowIfNull(setup);
        UnitFile? unit = null;
        string? error = null;
        try
        {
            unit = UnitFile.Load(setup.UnitPath);
        }
        catch (ArgumentException ex)
        {
            error = ex.Message;
        }

        var modules = setup.Robot.Modules.Modules.Select(module =>
        {
            var recorded = unit?.Module(module.Id);
            var motors = module.Motors.Select(m => new MotorConfig(setup.Robot, module, m).FullName).Select(name =>
            {
                var pot = recorded?.PotCalibration?.GetValueOrDefault(name);
                return new UnitMotorView(name, pot is not null, pot?.Verified == true, pot?.WorstDeg, pot?.Date);
            });
            return new UnitModuleView(module.Id, module.Name, recorded is not null, recorded?.FirmwareVersion, [.. motors]);
        });
        return new UnitView(setup.Unit, setup.UnitPath, unit?.Date, error, [.. modules]);
    }
}

/// <summary>One module of a <see cref="UnitView"/>.</summary>
/// <param name="Id">Its robot-file ID.</param>
/// <param name="Name">Its name.</param>
/// <param name="Commissioned">True when the unit file records it (numbered, every parameter written and verified).</param>
/// <param name="Firmware">The firmware version it reported when commissioned, or null.</param>
/// <param name="Motors">Its motors.</param>
public sealed record UnitModuleView(int Id, string Name, bool Commissioned, int? Firmware, IReadOnlyList<UnitMotorView> Motors);

/// <summary>One motor's pot calibration in a <see cref="UnitView"/>.</summary>
/// <param name="Name">The motor, <c>arm.joint</c>.</param>
/// <param name="Calibrated">True when its table was written into its module.</param>
/// <param name="Verified">True when the verification sweep stayed within its bound.</param>
/// <param name="WorstDeg">The verification's worst pot/encoder disagreement, degrees, or null.</param>
/// <param name="Date">When the table was written, or null.</param>
public sealed record UnitMotorView(string Name, bool Calibrated, bool Verified, double? WorstDeg, string? Date);
