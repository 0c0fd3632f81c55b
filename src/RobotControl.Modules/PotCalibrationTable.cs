using RobotControl.Bus.Protocol;

namespace RobotControl.Modules;

/// <summary>
/// A motor's pot calibration as its module keeps it (the control table's <c>pot_cal_*</c> fields): <see cref="Count"/>
/// pot readings taken at Hall-count positions <see cref="Pos0"/>, <see cref="Pos0"/> + <see cref="Step"/>, ... The
/// one pot-calibration type on the host: <see cref="For"/> computes it from the robot file (what is written into the
/// module), <see cref="Decode"/> reads it back from the module's persistent area, and <see cref="PositionAt"/> turns a
/// reading into a position exactly as the firmware does (piecewise-linear, nearest point outside the table).
/// </summary>
/// <param name="Count">Points in use (fewer than 2: uncalibrated).</param>
/// <param name="Pos0">Position of the first point, Hall counts at the axis output.</param>
/// <param name="Step">Counts between points.</param>
/// <param name="Raw">The pot reading at each point.</param>
public sealed record PotCalibrationTable(int Count, long Pos0, long Step, IReadOnlyList<long> Raw)
{
    /// <summary>Calibration points a module keeps (the control table's <c>pot_cal_raw*</c> fields).</summary>
    public static int MaxPoints { get; } = ControlTable.Firmware.Fields.Count(f => f.Name.StartsWith("pot_cal_raw", StringComparison.Ordinal));

    /// <summary>True when the motor can be homed from its pot (at least two points).</summary>
    public bool IsCalibrated => Count >= 2;

    /// <summary>The calibration the robot file gives <paramref name="config"/>'s motor: points evenly spaced in Hall counts over the pot's calibrated range.</summary>
    public static PotCalibrationTable For(MotorConfig config)
    {
        ArgumentNullException.ThrowIfNull(config);
        var pot = config.Motor.Pot;
        var n = MaxPoints;
        var pos0 = config.ToCounts(pot.MinRad);
        var step = (int)Math.Round((config.ToCounts(pot.MaxRad) - pos0) / (double)(n - 1));
        var raw = new long[n];
        for (var k = 0; k < n; k++)
        {
            raw[k] = (long)Math.Round(pot.Reading(config.ToRadians(pos0 + ((long)k * step))));
        }

        return new PotCalibrationTable(n, pos0, step, raw);
    }

    /// <summary>The calibration of channel <paramref name="channel"/> in a module's persistent area (<paramref name="block"/> read from address <paramref name="start"/>).</summary>
    public static PotCalibrationTable Decode(ControlTable table, byte[] block, int start, int channel)
    {
        ArgumentNullException.ThrowIfNull(table);
        ArgumentNullException.ThrowIfNull(block);
        long Field(string name) => table[name].Decode(block.AsSpan(table[name].At(channel) - start));
        var count = (int)Field("pot_cal_count");
        var raw = new long[MaxPoints];
        for (var k = 0; k < raw.Length; k++)
        {
            raw[k] = Field($"pot_cal_raw{k}");
        }

        return new PotCalibrationTable(count, Field("pot_cal_pos0"), Field("pot_cal_step"), raw);
    }

    /// <summary>The position (Hall counts) the firmware derives from pot reading <paramref name="raw"/>; 0 when uncalibrated.</summary>
    public long PositionAt(int raw)
    {
        var n = Math.Min(Count, Raw.Count);
        if (n < 2)
        {
            return 0;
        }

        var best = Pos0;
        var bestDistance = long.MaxValue;
        for (var i = 0; i + 1 < n; i++)
        {
            var r0 = Raw[i];
            var r1 = Raw[i + 1];
            if (((r0 <= raw && raw <= r1) || (r1 <= raw && raw <= r0)) && r0 != r1)
            {
                return Pos0 + (i * Step) + ((raw - r0) * Step / (r1 - r0));
            }

            if (Math.Abs(raw - r0) < bestDistance)
            {
                bestDistance = Math.Abs(raw - r0);
                best = Pos0 + (i * Step);
            }

            if (Math.Abs(raw - r1) < bestDistance)
            {
                bestDistance = Math.Abs(raw - r1);
                best = Pos0 + ((i + 1) * Step);
            }
        }

        return best;
    }
}
