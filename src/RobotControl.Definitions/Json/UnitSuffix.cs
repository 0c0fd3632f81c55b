namespace RobotControl.Definitions.Json;

/// <summary>Unit suffixes of data-file field names (<c>a_mm</c>, <c>stall_torque_mNm</c>), to name a wrong unit.</summary>
internal static class UnitSuffix
{
    private static readonly string[] Known =
    [
        "_mm", "_cm", "_m", "_in", "_deg", "_rad", "_mNm", "_Nm", "_rpm", "_rad_s", "_pct", "_ohm", "_A", "_V", "_uH",
        "_ms", "_s", "_g", "_kg", "_g_cm2", "_K_per_W", "_C", "_N", "_mm_s", "_cm2", "_cm3", "_mNm_per_rpm",
        "_rpm_per_V", "_mV_per_rpm", "_mNm_per_A", "_rad_per_s",
    ];

    /// <summary>The name without its longest known unit suffix.</summary>
    public static string Strip(string name)
    {
        var best = string.Empty;
        foreach (var suffix in Known)
        {
            if (name.EndsWith(suffix, StringComparison.Ordinal) && suffix.Length > best.Length && name.Length > suffix.Length)
            {
                best = suffix;
            }
        }

        return name[..^best.Length];
    }

    /// <summary>The unit of the name (without the underscore), or empty.</summary>
    public static string Of(string name) => name[Strip(name).Length..].TrimStart('_');
}
