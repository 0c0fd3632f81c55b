using System.Runtime.CompilerServices;

namespace RobotControl.Plugins.CoppeliaSim;

/// <summary>Joint values of every arm (arm-major) with the loop tick they belong to; a value type for <c>LatestValue</c>.</summary>
internal struct JointFrame
{
    /// <summary>Most joints the frame holds (all arms together).</summary>
    public const int Capacity = 32;

    /// <summary>The values, radians.</summary>
    public JointValues Values;

    /// <summary>The loop tick the values belong to.</summary>
    public long Tick;
}

/// <summary>Fixed storage of <see cref="JointFrame.Capacity"/> doubles (no allocation when copied).</summary>
[InlineArray(JointFrame.Capacity)]
internal struct JointValues
{
    private double _first;
}
