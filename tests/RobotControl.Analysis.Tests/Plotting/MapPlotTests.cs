using RobotControl.Analysis.Plotting;

namespace RobotControl.Analysis.Tests.Plotting;

public sealed class MapPlotTests
{
    private static readonly Lazy<AnalysisReport> Crb = new(() => CapabilityAnalyzer.Run(TestRobots.Crb, new AnalysisOptions { Workspace = false }));

    [Fact]
    public void The_font_is_registered_and_has_glyphs()
    {
        Assert.Equal("DejaVu Sans", PlotFont.Ensure());

        var typeface = ScottPlot.Fonts.GetTypeface(PlotFont.Family, bold: true, italic: false);

        Assert.Equal("DejaVu Sans", typeface.FamilyName);
        Assert.True(typeface.GlyphCount > 1000);
        Assert.Equal(PlotFont.Family, ScottPlot.Fonts.Default);
    }

    [Fact]
    public void A_map_is_a_png_of_the_expected_size_with_a_coloured_map_and_text()
    {
        var sweep = Crb.Value.Sweep;
        var png = MapPlot.RenderPng("CRB-1.0", "test subtitle", sweep, ToolPlaneGrid.For(sweep), Content(sweep.Reference.Velocity[2], 100));

        var image = DecodedPng.Decode(png);

        Assert.Equal((MapPlot.Width, MapPlot.Height), (image.Width, image.Height));
        Assert.True(image.DistinctColours() > 200, $"only {image.DistinctColours()} colours");

        // Title and subtitle are drawn: dark text pixels in the top band, above the data area.
        Assert.True(image.DarkPixels(0, 60) > 500, $"{image.DarkPixels(0, 60)} dark pixels in the title band");
    }

    [Fact]
    public void Different_quantities_give_different_maps_and_a_constant_one_has_few_colours()
    {
        var sweep = Crb.Value.Sweep;
        var plane = ToolPlaneGrid.For(sweep);

        var vx = DecodedPng.Decode(MapPlot.RenderPng("CRB-1.0", "s", sweep, plane, Content(sweep.Reference.Velocity[0], null)));
        var vz = DecodedPng.Decode(MapPlot.RenderPng("CRB-1.0", "s", sweep, plane, Content(sweep.Reference.Velocity[2], null)));
        var constant = DecodedPng.Decode(MapPlot.RenderPng("CRB-1.0", "s", sweep, plane, Content(new double[sweep.Count], null)));

        var differing = Enumerable.Range(0, vx.Pixels.Length).Count(i => vx.Pixels[i] != vz.Pixels[i]);
        Assert.True(differing > 50_000, $"only {differing} pixels differ");

        // Left of the colour bar (x >= 830): the constant map is one colour (plus blends at its edge), Vx is a gradient.
        var constantColours = constant.DistinctColours(0, 800);
        var vxColours = vx.DistinctColours(0, 800);
        Assert.True(vxColours > 150, $"Vx map: {vxColours} colours");
        Assert.True(constantColours < vxColours / 4, $"constant map: {constantColours} colours, Vx: {vxColours}");
    }

    private static MapContent Content(IReadOnlyList<double> values, double? requirement) =>
        new(values, "V", "largest tool speed", "mm/s", requirement);
}
