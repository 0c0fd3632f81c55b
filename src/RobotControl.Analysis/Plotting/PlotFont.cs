using ScottPlot;

namespace RobotControl.Analysis.Plotting;

/// <summary>
/// The maps' typeface. The SkiaSharp native build used here (NativeAssets.Linux.NoDependencies) has no fontconfig: it
/// only scans <c>/usr/share/fonts</c> and picks whichever family it meets first (DejaVu Serif on a Debian machine with
/// fonts-dejavu-core), and without any font file all text silently renders as nothing. So the maps name their font
/// explicitly: DejaVu Sans (regular and bold) from the font files of the fonts-dejavu-core package
/// (<c>tools/bootstrap.sh</c> installs it), registered with ScottPlot once and made its default.
/// </summary>
internal static class PlotFont
{
    /// <summary>Family name the maps use.</summary>
    public const string Family = "DejaVu Sans";

    private const string Regular = "DejaVuSans.ttf";
    private const string Bold = "DejaVuSans-Bold.ttf";

    /// <summary>Directories searched for the font files: Debian/Ubuntu, Fedora, Arch.</summary>
    private static readonly string[] Directories =
        ["/usr/share/fonts/truetype/dejavu", "/usr/share/fonts/dejavu-sans-fonts", "/usr/share/fonts/dejavu", "/usr/share/fonts/TTF"];

    private static readonly Lazy<string> Registered = new(Register, LazyThreadSafetyMode.ExecutionAndPublication);

    /// <summary>Registers the font with ScottPlot (once; thread-safe) and returns its family name.</summary>
    /// <exception cref="InvalidOperationException">The font files are not installed.</exception>
    public static string Ensure() => Registered.Value;

    private static string Register()
    {
        var directory = Directories.FirstOrDefault(d => File.Exists(Path.Combine(d, Regular)) && File.Exists(Path.Combine(d, Bold)))
            ?? throw new InvalidOperationException(
                $"the maps need the {Family} font ({Regular} and {Bold}), found in none of {string.Join(", ", Directories)}; " +
                "install the Debian package fonts-dejavu-core (tools/bootstrap.sh does)");
        Fonts.AddFontFile(Family, Path.Combine(directory, Regular), bold: false, italic: false);
        Fonts.AddFontFile(Family, Path.Combine(directory, Bold), bold: true, italic: false);
        Fonts.Default = Family;
        return Family;
    }
}
