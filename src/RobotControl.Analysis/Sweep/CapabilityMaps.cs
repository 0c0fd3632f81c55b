namespace RobotControl.Analysis.Sweep;

/// <summary>Per-point velocity and force maps of one method (index = x index · y count + y index).</summary>
public sealed class CapabilityMaps
{
    internal CapabilityMaps(int count)
    {
        Velocity = [new double[count], new double[count], new double[count]];
        Force = [new double[count], new double[count], new double[count]];
    }

    /// <summary>Largest tool speed along X, Y, Z (index 0..2) per point, mm/s.</summary>
    public double[][] Velocity { get; }

    /// <summary>Largest holdable tool force along X, Y, Z (index 0..2) per point, N (0.1 N grid, at most 30 N).</summary>
    public double[][] Force { get; }
}
