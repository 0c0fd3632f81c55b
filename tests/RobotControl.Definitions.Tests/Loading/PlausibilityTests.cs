using RobotControl.Definitions.Loading;

namespace RobotControl.Definitions.Tests.Loading;

/// <summary>Values a robot could not have (typos such as <c>d_mm: 1e300</c>) are refused with the field's path.</summary>
public sealed class PlausibilityTests : IDisposable
{
    private readonly RobotFiles _files = new();

    public void Dispose() => _files.Dispose();

    [Theory]
    [InlineData("d_mm", 1e300)]
    [InlineData("a_mm", -20_000)]
    public void An_implausible_link_length_is_refused(string field, double value)
    {
        var json = RobotFiles.Json("lb-1.0.json");
        json["dh"]![2]![field] = value;

        var error = Assert.Throws<RobotDataException>(() => RobotLoader.Load(_files.Write(json)));

        Assert.Contains($"$.dh[2].{field}", error.Message, StringComparison.Ordinal);
        Assert.Contains("must be at", error.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void A_limit_at_the_bound_still_loads()
    {
        var json = RobotFiles.Json("lb-1.0.json");
        json["dh"]![2]!["d_mm"] = 10_000;

        Assert.Equal("LB-1.0", RobotLoader.Load(_files.Write(json)).Name);
    }
}
