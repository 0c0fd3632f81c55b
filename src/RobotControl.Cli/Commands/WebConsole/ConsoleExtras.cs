using RobotControl.Cli.Commands.Run;

namespace RobotControl.Cli.Commands.WebConsole;

/// <summary>The console command's options for the surgeon's station: injected faults, the page to open, kiosk mode, the report.</summary>
/// <param name="Inject">The <c>--inject</c> text, or null.</param>
/// <param name="Page">The <c>--page</c> to open, or null (the bus page).</param>
/// <param name="Kiosk">True: <c>--kiosk</c>.</param>
/// <param name="Report">The <c>--report</c> file written at the stop, or null.</param>
/// <param name="Scheduling"><c>--rt-priority</c> and <c>--cpu</c>, checked as <c>run</c> checks them.</param>
internal sealed record ConsoleExtras(string? Inject, string? Page, bool Kiosk, string? Report, RunExtras Scheduling)
{
    /// <summary>The console's pages (the front-end's routes).</summary>
    public static readonly IReadOnlyList<string> Pages = ["bus", "plots", "view3d", "status", "editor", "surgeon"];

    /// <summary>Refuses an unknown page.</summary>
    /// <exception cref="FormatException">The page is not one of <see cref="Pages"/>.</exception>
    public void CheckPage()
    {
        if (Page is not null && !Pages.Contains(Page))
        {
            throw new FormatException($"--page '{Page}': no such page (pages: {string.Join(", ", Pages)})");
        }
    }

    /// <summary>The URL to open: the console's, on the page asked for.</summary>
    public Uri Url(Uri open) => Page is null ? open : new UriBuilder(open) { Fragment = Page }.Uri;
}
