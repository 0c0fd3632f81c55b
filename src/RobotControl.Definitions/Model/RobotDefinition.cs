namespace RobotControl.Definitions.Model;

/// <summary>
/// One robot design as read from its data file in <c>hardware/robots/</c>: the single model of the robot that
/// kinematics, inverse kinematics, capability analysis, the robot layer and the virtual robot all read.
/// Lengths are millimetres and angles radians once loaded; the file itself uses the units named in its fields.
/// </summary>
public sealed class RobotDefinition
{
    internal RobotDefinition(
        string name,
        string description,
        string sourceFile,
        double shoulderCrossSectionCm2,
        IReadOnlyList<JointDefinition> joints,
        IReadOnlyList<DhRow> dh,
        IReadOnlyList<int> positionJoints,
        IReadOnlyList<ActuatorDefinition> actuators,
        ToolDefinition tool,
        IReadOnlyList<ArmPlacement> arms,
        Vector3Data mirrorPlaneNormal,
        CrossSectionDefinition crossSection,
        RequirementsDefinition requirements,
        IReadOnlyList<MotorDefinition> motors,
        IReadOnlyList<GearheadDefinition> gearheads)
    {
        Name = name;
        Description = description;
        SourceFile = sourceFile;
        ShoulderCrossSectionCm2 = shoulderCrossSectionCm2;
        Joints = joints;
        Dh = dh;
        PositionJoints = positionJoints;
        Actuators = actuators;
        Tool = tool;
        Arms = arms;
        MirrorPlaneNormal = mirrorPlaneNormal;
        CrossSection = crossSection;
        Requirements = requirements;
        Motors = motors;
        Gearheads = gearheads;
    }

    /// <summary>Design name, e.g. <c>LB-1.0</c>.</summary>
    public string Name { get; }

    /// <summary>Free-text description from the file.</summary>
    public string Description { get; }

    /// <summary>Full path of the file this definition was loaded from.</summary>
    public string SourceFile { get; }

    /// <summary>Inserted shoulder cross-section, cm².</summary>
    public double ShoulderCrossSectionCm2 { get; }

    /// <summary>Kinematic joints in joint-vector order (phi1, phi2, ...).</summary>
    public IReadOnlyList<JointDefinition> Joints { get; }

    /// <summary>DH rows in chain order, including fixed rows.</summary>
    public IReadOnlyList<DhRow> Dh { get; }

    /// <summary>Indices of the joints that position the tool tip (the closed-form and capability-analysis subset).</summary>
    public IReadOnlyList<int> PositionJoints { get; }

    /// <summary>Driven axes (one motor each) in file order, the tool's open/close drive included.</summary>
    public IReadOnlyList<ActuatorDefinition> Actuators { get; }

    /// <summary>Tool data (jaw range, lead screw, linkage).</summary>
    public ToolDefinition Tool { get; }

    /// <summary>Placement of the robot's arms (right is the modelled arm, left its mirror).</summary>
    public IReadOnlyList<ArmPlacement> Arms { get; }

    /// <summary>Normal of the plane (through the base origin) that mirrors the right arm into the left one.</summary>
    public Vector3Data MirrorPlaneNormal { get; }

    /// <summary>The reference design's capability-analysis cross-section.</summary>
    public CrossSectionDefinition CrossSection { get; }

    /// <summary>Force and velocity requirements the design is checked against.</summary>
    public RequirementsDefinition Requirements { get; }

    /// <summary>Motors from the component catalogues the file references.</summary>
    public IReadOnlyList<MotorDefinition> Motors { get; }

    /// <summary>Gearhead series from the component catalogues the file references.</summary>
    public IReadOnlyList<GearheadDefinition> Gearheads { get; }

    /// <summary>The motor-control modules and bus settings (the file's <c>modules</c> section; empty without one).</summary>
    public ModuleLayout Modules { get; internal init; } = ModuleLayout.Empty;

    /// <summary>The safety supervisor's thresholds and safe states (the file's <c>safety</c> section; the defaults without one).</summary>
    public SafetyLimits Safety { get; internal init; } = new();

    /// <summary>Number of kinematic joints.</summary>
    public int JointCount => Joints.Count;

    /// <summary>Index of the joint with the given name, or -1.</summary>
    public int IndexOfJoint(string name)
    {
        for (var i = 0; i < Joints.Count; i++)
        {
            if (Joints[i].Name == name)
            {
                return i;
            }
        }

        return -1;
    }

    /// <summary>The motor of the given model (it exists: the loader checked every reference).</summary>
    public MotorDefinition Motor(string model) => Motors.First(m => m.Model == model);

    /// <summary>The gearhead series of the given name (it exists: the loader checked every reference).</summary>
    public GearheadDefinition Gearhead(string series) => Gearheads.First(g => g.Series == series);
}
