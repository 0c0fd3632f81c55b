using RobotControl.Analysis.Plotting;

namespace RobotControl.Analysis.Tests.Plotting;

public sealed class BitmapFontTests
{
    [Fact]
    public void The_font_covers_digits_letters_and_the_punctuation_the_plots_use()
    {
        foreach (var c in "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz .,:;-+=_/()[]%'!?<>*#|^°³")
        {
            Assert.True(BitmapFont.HasGlyph(c), $"no glyph for '{c}'");
        }
    }

    [Fact]
    public void Text_draws_ink_within_its_measured_box_and_glyphs_differ()
    {
        var a = new RgbImage(100, 30);
        var b = new RgbImage(100, 30);
        BitmapFont.Draw(a, "Fx 1.5", 2, 2, 2, Rgb.Black);
        BitmapFont.Draw(b, "Fy 1.5", 2, 2, 2, Rgb.Black);
        var width = BitmapFont.MeasureWidth("Fx 1.5", 2);

        var ink = 0;
        for (var y = 0; y < a.Height; y++)
        {
            for (var x = 0; x < a.Width; x++)
            {
                if (a.GetPixel(x, y) == Rgb.Black)
                {
                    ink++;
                    Assert.InRange(x, 2, 2 + width - 1);
                    Assert.InRange(y, 2, 2 + (BitmapFont.GlyphHeight * 2) - 1);
                }
            }
        }

        Assert.True(ink > 50);
        Assert.NotEqual(a.Pixels.ToArray(), b.Pixels.ToArray());
    }
}
