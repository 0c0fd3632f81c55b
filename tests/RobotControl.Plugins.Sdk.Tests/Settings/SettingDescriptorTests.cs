using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Plugins.Sdk.Tests.Settings;

/// <summary>A setting's range as inputs use it (<see cref="SettingDescriptor.Accepts"/>) and looked up by name.</summary>
public sealed class SettingDescriptorTests
{
    private static readonly SettingsSchema Schema = SettingsSchema.For(typeof(RangedSettings));

    [Theory]
    [InlineData(0.01, true)] // both ends belong to the range
    [InlineData(10, true)]
    [InlineData(0.5, true)]
    [InlineData(0.0099, false)]
    [InlineData(10.001, false)]
    [InlineData(double.NaN, false)]
    [InlineData(double.PositiveInfinity, false)]
    public void A_bounded_setting_accepts_finite_values_inside_its_range(double value, bool accepted)
    {
        Assert.Equal(accepted, Schema.Find("ratio")!.Accepts(value));
    }

    [Theory]
    [InlineData(-1e300, true)] // no bound below: NaN means unbounded
    [InlineData(5, true)]
    [InlineData(5.5, false)]
    [InlineData(double.NegativeInfinity, false)] // unbounded still means finite
    public void A_missing_bound_is_no_bound_but_the_value_must_be_finite(double value, bool accepted)
    {
        Assert.Equal(accepted, Schema.Find("limit")!.Accepts(value));
    }

    [Fact]
    public void Find_takes_the_graph_file_name_and_says_null_for_an_unknown_one()
    {
        Assert.Equal(nameof(RangedSettings.Ratio), Schema.Find("ratio")!.Property.Name);
        Assert.Null(Schema.Find("Ratio"));
        Assert.Null(Schema.Find("speed"));
    }

    private sealed record RangedSettings : PluginSettings
    {
        [Setting("A ratio.", Minimum = 0.01, Maximum = 10)]
        public double Ratio { get; init; } = 1;

        [Setting("Bounded above only.", Maximum = 5)]
        public double Limit { get; init; }
    }
}
