using RobotControl.Analysis.Plotting;

namespace RobotControl.Analysis.Tests.Plotting;

public sealed class ToolPlaneGridTests
{
    private static readonly Lazy<AnalysisReport> Lb = new(() => CapabilityAnalyzer.Run(TestRobots.Lb, new AnalysisOptions { Workspace = false }));

    [Fact]
    public void The_reference_cross_section_is_drawn_in_the_base_x_y_plane_with_square_cells()
    {
        var plane = ToolPlaneGrid.For(Lb.Value.Sweep);

        Assert.Equal(("x", "y"), (plane.HorizontalName, plane.VerticalName));
        Assert.Equal(plane.Right - plane.Left, plane.Columns * plane.CellSize, 9);
        Assert.Equal(480, Math.Max(plane.Columns, plane.Rows));
        var position = Lb.Value.Sweep.Position;
        Assert.InRange(position[0].Min(), plane.Left, plane.Right);
        Assert.InRange(position[0].Max(), plane.Left, plane.Right);
        Assert.InRange(position[1].Min(), plane.Bottom, plane.Top);
        Assert.InRange(position[1].Max(), plane.Bottom, plane.Top);
    }

    [Fact]
    public void A_linear_function_of_the_tool_position_is_reproduced_where_reached_and_NaN_elsewhere()
    {
        var sweep = Lb.Value.Sweep;
        var plane = ToolPlaneGrid.For(sweep);
        static double F(double x, double y) => (2 * x) - (3 * y) + 7;
        var values = Enumerable.Range(0, sweep.Count).Select(i => F(sweep.Position[0][i], sweep.Position[1][i])).ToArray();

        var grid = plane.Resample(values);

        Assert.Equal(plane.Rows, grid.GetLength(0));
        Assert.Equal(plane.Columns, grid.GetLength(1));
        int reached = 0, empty = 0;
        for (var row = 0; row < plane.Rows; row++)
        {
            for (var column = 0; column < plane.Columns; column++)
            {
                if (double.IsNaN(grid[row, column]))
                {
                    empty++;
                    continue;
                }

                reached++;
                var x = plane.Left + ((column + 0.5) * plane.CellSize);
                var y = plane.Top - ((row + 0.5) * plane.CellSize);
                Assert.Equal(F(x, y), grid[row, column], 6);
            }
        }

        // The LB cross-section is a crescent: it fills part of its bounding box, with the hole near the base.
        var total = plane.Rows * plane.Columns;
        Assert.InRange(reached, total / 4, total * 3 / 4);
        Assert.Equal(total, reached + empty);
        Assert.True(double.IsNaN(grid[plane.Rows / 2, 0]), "the left edge at mid-height is padding, not reached");
    }

    [Fact]
    public void Values_must_match_the_sweep()
    {
        var plane = ToolPlaneGrid.For(Lb.Value.Sweep);

        Assert.Throws<ArgumentException>(() => plane.Resample(new double[10]));
    }
}
