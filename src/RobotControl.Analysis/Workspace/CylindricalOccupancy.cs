using System.Numerics;
using RobotControl.Kinematics.Geometry;

namespace RobotControl.Analysis.Workspace;

/// <summary>
/// Occupancy of a region in cylindrical cells around an axis (origin <see cref="Origin"/>, direction
/// <see cref="Axis"/>): radial and axial cells of size h, angular bins of at most h of arc at the outer radius. Each
/// (radius, height) cell holds a bitset over the angular bins, so rotating the region about the axis is a shift of
/// bits and sweeping it over an angle range is a dilation of each bitset (<see cref="Dilate"/>).
/// </summary>
internal sealed class CylindricalOccupancy
{
    private const byte Empty = 0;
    private const byte Full = 1;
    private const byte Partial = 2;

    private readonly ulong[] _bits;
    private readonly byte[] _cellState;
    private readonly double _inverseCell;
    private readonly double _inverseBin;

    public CylindricalOccupancy(Vector3d origin, Vector3d axis, double radiusMm, double cellMm)
    {
        Origin = origin;
        Axis = axis.Normalized();
        var seed = Math.Abs(Axis.X) < 0.9 ? Vector3d.UnitX : Vector3d.UnitY;
        U = (seed - (Axis * Vector3d.Dot(Axis, seed))).Normalized();
        V = Vector3d.Cross(Axis, U);
        CellMm = cellMm;
        RadiusMm = radiusMm;
        RadialCells = (int)Math.Ceiling(radiusMm / cellMm) + 1;
        AxialCells = (2 * RadialCells) + 1;
        AxialMinMm = -(RadialCells + 0.5) * cellMm;
        Words = (int)Math.Ceiling(2 * Math.PI * radiusMm / cellMm / 64.0);
        Bins = Words * 64;
        BinRad = 2 * Math.PI / Bins;
        _inverseCell = 1.0 / cellMm;
        _inverseBin = 1.0 / BinRad;
        _bits = new ulong[(long)RadialCells * AxialCells * Words];
        _cellState = new byte[RadialCells * AxialCells];
    }

    public Vector3d Origin { get; }

    public Vector3d Axis { get; }

    /// <summary>Unit vector perpendicular to the axis: angle 0.</summary>
    public Vector3d U { get; }

    /// <summary>Axis × U: angle +pi/2.</summary>
    public Vector3d V { get; }

    public double CellMm { get; }

    public double RadiusMm { get; }

    public int RadialCells { get; }

    public int AxialCells { get; }

    public double AxialMinMm { get; }

    public int Words { get; }

    public int Bins { get; }

    public double BinRad { get; }

    /// <summary>Marks the cell holding cylindrical coordinates (radius, height, angle in [-pi, pi]). Thread-safe.</summary>
    public void Mark(double radius, double height, double angle)
    {
        var ir = (int)(radius * _inverseCell);
        var iz = (int)Math.Floor((height - AxialMinMm) * _inverseCell);
        if ((uint)ir >= (uint)RadialCells || (uint)iz >= (uint)AxialCells)
        {
            throw new InvalidOperationException($"point at radius {radius} mm, height {height} mm lies outside the occupancy grid");
        }

        var bin = AngleBin(angle);
        var index = (((long)ir * AxialCells) + iz) * Words + (bin >> 6);
        var mask = 1UL << (bin & 63);
        if ((Volatile.Read(ref _bits[index]) & mask) == 0)
        {
            Interlocked.Or(ref _bits[index], mask);
        }
    }

    /// <summary>
    /// Sweeps the marked region about the axis by every angle in [<paramref name="minRad"/>, <paramref name="maxRad"/>]:
    /// each marked bin b covers round((max - min) / bin) bins from b + round(min / bin), so a marked angle, uniformly
    /// placed in its bin, becomes an arc of the right length on average (no half-bin bias at either end).
    /// </summary>
    public void Dilate(double minRad, double maxRad)
    {
        var kMin = (int)Math.Round(minRad * _inverseBin);
        var width = Math.Max(1, (int)Math.Round((maxRad - minRad) * _inverseBin));
        Parallel.For(0, RadialCells * AxialCells, () => new ulong[Words], (cell, _, scratch) =>
        {
            var words = _bits.AsSpan((int)((long)cell * Words), Words);
            if (!Any(words))
            {
                return scratch;
            }

            Array.Clear(scratch);
            if (width >= Bins)
            {
                scratch.AsSpan().Fill(ulong.MaxValue);
            }
            else
            {
                var start = 0;
                while (start < Bins)
                {
                    if (!IsSet(words, start))
                    {
                        start++;
                        continue;
                    }

                    var end = start;
                    while (end + 1 < Bins && IsSet(words, end + 1))
                    {
                        end++;
                    }

                    SetCircular(scratch, start + kMin, Math.Min(end - start + width, Bins));
                    start = end + 1;
                }
            }

            scratch.AsSpan().CopyTo(words);
            return scratch;
        }, _ => { });
        ClassifyCells();
    }

    /// <summary>True when the cell holding point <paramref name="point"/> (same frame as <see cref="Origin"/>) is occupied.</summary>
    public bool Contains(Vector3d point)
    {
        var d = point - Origin;
        var height = Vector3d.Dot(d, Axis);
        var x = Vector3d.Dot(d, U);
        var y = Vector3d.Dot(d, V);
        var ir = (int)(Math.Sqrt((x * x) + (y * y)) * _inverseCell);
        var iz = (int)Math.Floor((height - AxialMinMm) * _inverseCell);
        if (ir >= RadialCells || (uint)iz >= (uint)AxialCells)
        {
            return false;
        }

        var cell = (ir * AxialCells) + iz;
        var state = _cellState[cell];
        if (state != Partial)
        {
            return state == Full;
        }

        var bin = AngleBin(FastAngle.Atan2(y, x));
        return (_bits[((long)cell * Words) + (bin >> 6)] & (1UL << (bin & 63))) != 0;
    }

    /// <summary>Exact volume of the occupied cells, mm³ (a cell at radial index i spans (i + 1/2) h³ · bin angle).</summary>
    public double VolumeMm3()
    {
        var volume = 0.0;
        var h3 = CellMm * CellMm * CellMm;
        for (var ir = 0; ir < RadialCells; ir++)
        {
            long count = 0;
            for (var iz = 0; iz < AxialCells; iz++)
            {
                foreach (var w in _bits.AsSpan((int)((((long)ir * AxialCells) + iz) * Words), Words))
                {
                    count += BitOperations.PopCount(w);
                }
            }

            volume += count * (ir + 0.5) * h3 * BinRad;
        }

        return volume;
    }

    private int AngleBin(double angle)
    {
        var bin = (int)((angle + Math.PI) * _inverseBin);
        return bin >= Bins ? bin - Bins : Math.Max(bin, 0);
    }

    private void ClassifyCells()
    {
        for (var cell = 0; cell < _cellState.Length; cell++)
        {
            var words = _bits.AsSpan((int)((long)cell * Words), Words);
            var all = true;
            var any = false;
            foreach (var w in words)
            {
                all &= w == ulong.MaxValue;
                any |= w != 0;
            }

            _cellState[cell] = all ? Full : any ? Partial : Empty;
        }
    }

    private static bool Any(Span<ulong> words)
    {
        foreach (var w in words)
        {
            if (w != 0)
            {
                return true;
            }
        }

        return false;
    }

    private static bool IsSet(Span<ulong> words, int bin) => (words[bin >> 6] & (1UL << (bin & 63))) != 0;

    private void SetCircular(ulong[] words, int start, int count)
    {
        start %= Bins;
        if (start < 0)
        {
            start += Bins;
        }

        for (var i = 0; i < count; i++)
        {
            var bin = start + i;
            if (bin >= Bins)
            {
                bin -= Bins;
            }

            words[bin >> 6] |= 1UL << (bin & 63);
        }
    }
}
