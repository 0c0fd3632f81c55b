using SkiaSharp;

namespace RobotControl.Analysis.Tests.Plotting;

/// <summary>A PNG file decoded with SkiaSharp, as 0xRRGGBB pixels row by row.</summary>
internal sealed class DecodedPng
{
    private DecodedPng(int width, int height, int[] pixels)
    {
        Width = width;
        Height = height;
        Pixels = pixels;
    }

    public int Width { get; }

    public int Height { get; }

    public int[] Pixels { get; }

    public static DecodedPng Decode(byte[] png)
    {
        Assert.Equal([0x89, (byte)'P', (byte)'N', (byte)'G', 0x0D, 0x0A, 0x1A, 0x0A], png[..8]);
        using var bitmap = SKBitmap.Decode(png);
        Assert.NotNull(bitmap);
        var pixels = new int[bitmap.Width * bitmap.Height];
        for (var y = 0; y < bitmap.Height; y++)
        {
            for (var x = 0; x < bitmap.Width; x++)
            {
                var c = bitmap.GetPixel(x, y);
                pixels[(y * bitmap.Width) + x] = (c.Red << 16) | (c.Green << 8) | c.Blue;
            }
        }

        return new DecodedPng(bitmap.Width, bitmap.Height, pixels);
    }

    public int At(int x, int y) => Pixels[(y * Width) + x];

    /// <summary>Distinct colours that are not grey (text, grid and background are grey; the colour map is not).</summary>
    public int DistinctColours() => DistinctColours(0, Width);

    /// <summary>Distinct colours that are not grey in columns [left, right).</summary>
    public int DistinctColours(int left, int right) =>
        Enumerable.Range(0, Height).SelectMany(y => Enumerable.Range(left, right - left).Select(x => At(x, y))).Where(p => !IsGrey(p)).Distinct().Count();

    /// <summary>Pixels darker than mid-grey in rows [top, bottom).</summary>
    public int DarkPixels(int top, int bottom) =>
        Enumerable.Range(top, bottom - top).Sum(y => Enumerable.Range(0, Width).Count(x => Luminance(At(x, y)) < 100));

    private static bool IsGrey(int p)
    {
        int r = (p >> 16) & 0xFF, g = (p >> 8) & 0xFF, b = p & 0xFF;
        return Math.Max(r, Math.Max(g, b)) - Math.Min(r, Math.Min(g, b)) < 16;
    }

    private static int Luminance(int p) => ((((p >> 16) & 0xFF) * 3) + (((p >> 8) & 0xFF) * 6) + (p & 0xFF)) / 10;
}
