using RobotControl.WebConsole.Tests.Web;
using Xunit.Abstractions;

namespace RobotControl.WebConsole.Tests.Editor;

/// <summary>The editor page's start-up (<see cref="StartUpTests"/>): the graph drawn, on the console with the editor.</summary>
[Collection(EditorCollection.Name)]
public sealed class EditorStartUpTests(EditorFixture console, ITestOutputHelper output)
{
    [Fact]
    public async Task The_editor_marks_its_graph_drawn_and_the_times_are_printed()
    {
        var times = await StartUpTests.Measure(console.Browser, console.Server, ["editor"], output);
        Assert.Equal(StartUpTests.Loads, times["editor"].Count);
    }
}
