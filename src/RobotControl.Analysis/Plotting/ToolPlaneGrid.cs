using RobotControl.Analysis.Sweep;

namespace RobotControl.Analysis.Plotting;

/// <summary>
/// A regular grid of square cells over the tool positions of a sweep, in the plane of the two base axes along which
/// the positions spread most (the reference cross-sections lie in the base x-y plane). Each sweep grid cell is split
/// into two triangles; a plane cell whose centre lies in a triangle takes the linear interpolation of the triangle's
/// three point values, every other cell is NaN (not reached by the sweep). The geometry is computed once and then
/// applied to every map of the sweep.
/// </summary>
internal sealed class ToolPlaneGrid
{
    private const int CellsAlongLongerSide = 480;
    private static readonly string[] Names = ["x", "y", "z"];

    // Per plane cell (row-major, row 0 at the top = largest vertical coordinate): the three sweep points, -1 if none.
    private readonly int[] _points;
    private readonly double[] _weights;

    private ToolPlaneGrid(int pointCount, int horizontal, int vertical, double left, double bottom, double cell, int columns, int rows)
    {
        PointCount = pointCount;
        HorizontalAxis = horizontal;
        VerticalAxis = vertical;
        Left = left;
        Bottom = bottom;
        CellSize = cell;
        Columns = columns;
        Rows = rows;
        _points = new int[3 * columns * rows];
        _weights = new double[3 * columns * rows];
        Array.Fill(_points, -1);
    }

    /// <summary>Sweep points the grid was built from.</summary>
    public int PointCount { get; }

    /// <summary>Base axis (0 = x, 1 = y, 2 = z) along the plot's horizontal.</summary>
    public int HorizontalAxis { get; }

    /// <summary>Base axis along the plot's vertical.</summary>
    public int VerticalAxis { get; }

    /// <summary>Name of the horizontal axis (<c>x</c>, <c>y</c> or <c>z</c>).</summary>
    public string HorizontalName => Names[HorizontalAxis];

    /// <summary>Name of the vertical axis.</summary>
    public string VerticalName => Names[VerticalAxis];

    /// <summary>Left edge of the grid, mm.</summary>
    public double Left { get; }

    /// <summary>Bottom edge of the grid, mm.</summary>
    public double Bottom { get; }

    /// <summary>Edge length of a cell, mm.</summary>
    public double CellSize { get; }

    /// <summary>Cells across.</summary>
    public int Columns { get; }

    /// <summary>Cells up.</summary>
    public int Rows { get; }

    /// <summary>Right edge of the grid, mm.</summary>
    public double Right => Left + (Columns * CellSize);

    /// <summary>Top edge of the grid, mm.</summary>
    public double Top => Bottom + (Rows * CellSize);

    /// <summary>Builds the grid over the tool positions of <paramref name="sweep"/>.</summary>
    public static ToolPlaneGrid For(SweepResult sweep)
    {
        ArgumentNullException.ThrowIfNull(sweep);
        var (ha, va) = PlotPlane(sweep.Position);
        var hs = sweep.Position[ha];
        var vs = sweep.Position[va];
        var (hMin, hMax) = Padded(hs);
        var (vMin, vMax) = Padded(vs);
        var cell = Math.Max(hMax - hMin, vMax - vMin) / CellsAlongLongerSide;
        var columns = (int)Math.Ceiling((hMax - hMin) / cell);
        var rows = (int)Math.Ceiling((vMax - vMin) / cell);
        var grid = new ToolPlaneGrid(sweep.Count, ha, va, hMin, vMin, cell, columns, rows);
        for (var ix = 0; ix + 1 < sweep.XCount; ix++)
        {
            for (var iy = 0; iy + 1 < sweep.YCount; iy++)
            {
                var a = (ix * sweep.YCount) + iy;
                var b = a + sweep.YCount;
                var c = b + 1;
                var d = a + 1;
                grid.Cover(hs, vs, a, b, c);
                grid.Cover(hs, vs, a, c, d);
            }
        }

        return grid;
    }

    /// <summary>
    /// The two base axes along which <paramref name="position"/> (x, y, z arrays) spreads most, in axis order.
    /// </summary>
    public static (int Horizontal, int Vertical) PlotPlane(double[][] position)
    {
        ArgumentNullException.ThrowIfNull(position);
        var spread = position.Select(p => p.Max() - p.Min()).ToArray();
        var smallest = Array.IndexOf(spread, spread.Min());
        var axes = Enumerable.Range(0, 3).Where(a => a != smallest).ToArray();
        return (axes[0], axes[1]);
    }

    /// <summary>
    /// <paramref name="values"/> (one per sweep point) interpolated onto the grid: [row, column], row 0 at the top;
    /// NaN where the sweep does not reach.
    /// </summary>
    public double[,] Resample(IReadOnlyList<double> values)
    {
        ArgumentNullException.ThrowIfNull(values);
        if (values.Count != PointCount)
        {
            throw new ArgumentException($"{values.Count} values for a sweep of {PointCount} points", nameof(values));
        }

        var result = new double[Rows, Columns];
        for (var row = 0; row < Rows; row++)
        {
            for (var column = 0; column < Columns; column++)
            {
                var k = 3 * ((row * Columns) + column);
                result[row, column] = _points[k] < 0
                    ? double.NaN
                    : (_weights[k] * values[_points[k]]) + (_weights[k + 1] * values[_points[k + 1]]) + (_weights[k + 2] * values[_points[k + 2]]);
            }
        }

        return result;
    }

    private static (double Min, double Max) Padded(double[] values)
    {
        var min = values.Min();
        var max = values.Max();
        var pad = Math.Max(0.03 * (max - min), 1.0);
        return (min - pad, max + pad);
    }

    /// <summary>Assigns the triangle p0 p1 p2 (sweep point indices) to the cells whose centres it contains.</summary>
    private void Cover(double[] hs, double[] vs, int p0, int p1, int p2)
    {
        double x0 = hs[p0], y0 = vs[p0], x1 = hs[p1], y1 = vs[p1], x2 = hs[p2], y2 = vs[p2];
        var area = ((x1 - x0) * (y2 - y0)) - ((x2 - x0) * (y1 - y0));
        if (Math.Abs(area) < 1e-12)
        {
            return;
        }

        // Column c has its centre at Left + (c + 0.5) cell; row r (from the top) at Top - (r + 0.5) cell.
        var cMin = Math.Max(0, (int)Math.Floor(((Math.Min(x0, Math.Min(x1, x2)) - Left) / CellSize) - 0.5));
        var cMax = Math.Min(Columns - 1, (int)Math.Ceiling(((Math.Max(x0, Math.Max(x1, x2)) - Left) / CellSize) - 0.5));
        var rMin = Math.Max(0, (int)Math.Floor(((Top - Math.Max(y0, Math.Max(y1, y2))) / CellSize) - 0.5));
        var rMax = Math.Min(Rows - 1, (int)Math.Ceiling(((Top - Math.Min(y0, Math.Min(y1, y2))) / CellSize) - 0.5));
        const double edge = -1e-9;
        for (var row = rMin; row <= rMax; row++)
        {
            var y = Top - ((row + 0.5) * CellSize);
            for (var column = cMin; column <= cMax; column++)
            {
                var x = Left + ((column + 0.5) * CellSize);
                var w0 = (((x1 - x) * (y2 - y)) - ((x2 - x) * (y1 - y))) / area;
                var w1 = (((x2 - x) * (y0 - y)) - ((x0 - x) * (y2 - y))) / area;
                var w2 = 1 - w0 - w1;
                if (w0 < edge || w1 < edge || w2 < edge)
                {
                    continue;
                }

                var k = 3 * ((row * Columns) + column);
                (_points[k], _points[k + 1], _points[k + 2]) = (p0, p1, p2);
                (_weights[k], _weights[k + 1], _weights[k + 2]) = (w0, w1, w2);
            }
        }
    }
}
