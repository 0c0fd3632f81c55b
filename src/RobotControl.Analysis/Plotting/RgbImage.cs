namespace RobotControl.Analysis.Plotting;

/// <summary>An 8-bit RGB raster with the few drawing operations the plots need (origin top-left).</summary>
public sealed class RgbImage
{
    private readonly byte[] _pixels;

    /// <summary>Creates a white image.</summary>
    public RgbImage(int width, int height)
    {
        ArgumentOutOfRangeException.ThrowIfNegativeOrZero(width);
        ArgumentOutOfRangeException.ThrowIfNegativeOrZero(height);
        Width = width;
        Height = height;
        _pixels = new byte[width * height * 3];
        Array.Fill(_pixels, (byte)255);
    }

    /// <summary>Width, pixels.</summary>
    public int Width { get; }

    /// <summary>Height, pixels.</summary>
    public int Height { get; }

    /// <summary>Row-major RGB bytes.</summary>
    public ReadOnlySpan<byte> Pixels => _pixels;

    /// <summary>Colour of pixel (x, y).</summary>
    public Rgb GetPixel(int x, int y)
    {
        var i = ((y * Width) + x) * 3;
        return new Rgb(_pixels[i], _pixels[i + 1], _pixels[i + 2]);
    }

    /// <summary>Sets pixel (x, y); points outside the image are ignored.</summary>
    public void SetPixel(int x, int y, Rgb colour)
    {
        if ((uint)x >= (uint)Width || (uint)y >= (uint)Height)
        {
            return;
        }

        var i = ((y * Width) + x) * 3;
        _pixels[i] = colour.R;
        _pixels[i + 1] = colour.G;
        _pixels[i + 2] = colour.B;
    }

    /// <summary>Fills the rectangle [x, x + w) × [y, y + h).</summary>
    public void FillRectangle(int x, int y, int w, int h, Rgb colour)
    {
        for (var yy = y; yy < y + h; yy++)
        {
            for (var xx = x; xx < x + w; xx++)
            {
                SetPixel(xx, yy, colour);
            }
        }
    }

    /// <summary>Draws a one-pixel line (Bresenham).</summary>
    public void DrawLine(int x0, int y0, int x1, int y1, Rgb colour)
    {
        int dx = Math.Abs(x1 - x0), sx = x0 < x1 ? 1 : -1;
        int dy = -Math.Abs(y1 - y0), sy = y0 < y1 ? 1 : -1;
        var err = dx + dy;
        while (true)
        {
            SetPixel(x0, y0, colour);
            if (x0 == x1 && y0 == y1)
            {
                return;
            }

            var e2 = 2 * err;
            if (e2 >= dy)
            {
                err += dy;
                x0 += sx;
            }

            if (e2 <= dx)
            {
                err += dx;
                y0 += sy;
            }
        }
    }

    /// <summary>Outlines the rectangle [x, x + w) × [y, y + h).</summary>
    public void DrawRectangle(int x, int y, int w, int h, Rgb colour)
    {
        DrawLine(x, y, x + w - 1, y, colour);
        DrawLine(x, y + h - 1, x + w - 1, y + h - 1, colour);
        DrawLine(x, y, x, y + h - 1, colour);
        DrawLine(x + w - 1, y, x + w - 1, y + h - 1, colour);
    }
}

/// <summary>An 8-bit RGB colour.</summary>
/// <param name="R">Red.</param>
/// <param name="G">Green.</param>
/// <param name="B">Blue.</param>
public readonly record struct Rgb(byte R, byte G, byte B)
{
    /// <summary>Black.</summary>
    public static Rgb Black => new(0, 0, 0);

    /// <summary>White.</summary>
    public static Rgb White => new(255, 255, 255);

    /// <summary>Grey of the given level.</summary>
    public static Rgb Grey(byte level) => new(level, level, level);
}
