using RobotControl.Runtime.Discovery;

namespace RobotControl.Runtime.Tests.Discovery;

public sealed class PluginReferenceTests
{
    private static readonly PluginDescription Filter = new(
        "low_pass",
        "First-order low pass | per channel.",
        "Lab.LowPass",
        "Lab.Filters",
        "1.0.0",
        "1.2.0",
        "/plugins/Lab.Filters.dll",
        new PluginPorts(
            [new PortDescription("x", "mm", "raw x", 0, null)],
            [new PortDescription("x", "mm", "filtered x", 1.5, "hold_last_finite")]),
        null,
        [
            new SettingDescription("cutoff_hz", "number", "Hz", 0.1, null, 30.0, [], false, false, "Cut-off."),
            new SettingDescription("mode", "choice", "", null, null, "fast", ["fast", "slow"], false, false, "Mode."),
            new SettingDescription("file", "text", "", null, null, null, [], true, true, "CSV | file."),
            new SettingDescription("label", "text", "", null, null, "", [], false, false, "Label."),
        ]);

    [Fact]
    public void A_section_lists_ports_and_settings_as_markdown_tables_with_pipes_escaped()
    {
        var expected = """
            ## low_pass

            First-order low pass \| per channel. (`Lab.LowPass`, assembly `Lab.Filters`)

            | input | units | initial | description |
            |---|---|---|---|
            | `x` | mm | 0 | raw x |

            | output | units | initial | safe value | description |
            |---|---|---|---|---|
            | `x` | mm | 1.5 | hold_last_finite | filtered x |

            | setting | kind | units | range | default | description |
            |---|---|---|---|---|---|
            | `cutoff_hz` | number | Hz | 0.1 … ∞ | 30 | Cut-off. |
            | `mode` | choice |  | `fast`, `slow` | `fast` | Mode. |
            | `file` | text |  |  | (required) | CSV \| file. |
            | `label` | text |  |  | "" | Label. |


            """.ReplaceLineEndings("\n");
        Assert.Equal(expected, PluginReference.Section(Filter));
    }

    [Fact]
    public void A_type_without_ports_or_settings_says_so_and_the_document_ends_with_one_newline()
    {
        var bare = Filter with { Ports = null, PortsProblem = "needs /home/x/recording.csv", Settings = [] };
        var document = PluginReference.Document([bare], robotName: null);

        Assert.StartsWith("# Plug-in reference\n\nThe 1 plug-in types", document, StringComparison.Ordinal);
        Assert.Contains("Ports that depend on the robot are not listed (no robot given).", document, StringComparison.Ordinal);
        Assert.Contains("Ports: declared from its settings when created;", document, StringComparison.Ordinal);
        Assert.DoesNotContain("/home/x", document, StringComparison.Ordinal); // a local path stays out of a kept file
        Assert.EndsWith("\n\nNo settings.\n", document, StringComparison.Ordinal);
    }
}
