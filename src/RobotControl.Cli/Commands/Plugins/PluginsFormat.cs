namespace RobotControl.Cli.Commands.Plugins;

/// <summary>What <c>robotctl plugins</c> writes.</summary>
internal enum PluginsFormat
{
    /// <summary>Aligned text for people.</summary>
    Table,

    /// <summary>JSON for scripts (<c>--json</c>).</summary>
    Json,

    /// <summary>The Markdown reference (<c>--markdown</c>).</summary>
    Markdown,

    /// <summary>Both <c>--json</c> and <c>--markdown</c>: refused.</summary>
    Conflicting,
}
