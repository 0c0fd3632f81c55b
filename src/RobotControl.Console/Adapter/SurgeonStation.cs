using RobotControl.Host.Safety;
using RobotControl.Host.Session;
using RobotControl.Kinematics.Urdf;
using RobotControl.Kinematics.Workspace;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// The surgeon's station of the live session: hands and pedals found in the graph, faults in plain words, the
/// workspace, the scale factor.
/// <para>
/// Written by the web threads, once each, lazily (the hands found in the graph, the sampled workspace: built again at
/// worst, never changed); the scale factor is set by the bus's owner between cycles.
/// </para>
/// </summary>
internal sealed class SurgeonStation(RobotSession session, CommandQueue queue, SessionEvents events)
{
    /// <summary>Tool-tip samples per arm: every joint within its limits, and with one joint at a limit.</summary>
    private const int WorkspaceInterior = 4000;
    private const int WorkspaceWalls = 4000;

    private SurgeonHands? _hands;
    private WorkspaceView? _workspace;

    /// <inheritdoc cref="IConsoleSession.Surgeon"/>
    public SurgeonView View
    {
        get
        {
            // Trips since the last reset (leaving E_STOP), oldest first; both lists are copies taken under the supervisor's locks.
            var since = Supervisor.History.LastOrDefault(h => h.From == RunLevel.EStop)?.Timestamp ?? long.MinValue;
            var faults = Supervisor.Trips.Where(t => t.Timestamp > since)
                .Select(t => FaultWords.Describe(t, Robot, events.SecondsAt(t.Timestamp))).ToList();
            return new SurgeonView(Hands.Views(), Hands.Pedals, faults);
        }
    }

    /// <inheritdoc cref="IConsoleSession.Workspace"/>
    public WorkspaceView Workspace => _workspace ??= BuildWorkspace();

    private Definitions.Model.RobotDefinition Robot => session.Connection.Definition!;

    private SafetySupervisor Supervisor => session.Supervisor;

    private SurgeonHands Hands => _hands ??= new SurgeonHands(session.Graph.Document, session.Graph.Program, Robot);

    /// <inheritdoc cref="IConsoleSession.SetScaleAsync"/>
    public Task<CommandResult> SetScaleAsync(string arm, double ratio)
    {
        if (Hands.Of(arm ?? string.Empty) is not { } hand)
        {
            return Task.FromResult(CommandResult.Fail(CommandOutcome.NotFound, $"no hand drives an arm '{arm}' (hands: {string.Join(", ", Hands.Views().Select(h => h.Arm))})"));
        }

        if (hand.Scaling is null || !hand.ScaleSettable)
        {
            return Task.FromResult(CommandResult.Fail(CommandOutcome.Refused, hand.Scaling is null
                ? $"the {arm} hand has no scaling plug-in in the graph"
                : $"{hand.Scaling.Name}.ratio is wired in the graph: the console does not set it"));
        }

        if (hand.ScaleSetting is not { } range || !range.Accepts(ratio))
        {
            return CommandChecks.Bad($"scale factor {ratio} outside {hand.ScaleMin:G4}..{hand.ScaleMax:G4} (the ratio setting's range of {hand.Scaling.Name})");
        }

        // Applied between bus cycles: on the virtual robot the loop ticks on this thread, so the new ratio is in place
        // for the next tick; on a real bus the plug-in reads the input once per tick. The clutch holds the arm's target
        // while it is held and re-bases on release, so the tool tip does not jump.
        return queue.Submit(() =>
        {
            if (!hand.Clutched)
            {
                return CommandResult.Fail(CommandOutcome.Refused, hand.Clutch is null
                    ? $"the {arm} hand has no clutch: its scale factor cannot change without a jump"
                    : $"the {arm} scale factor changes only while the {arm} clutch is held ({hand.Clutch.Name} is released)");
            }

            var before = hand.Scale;
            hand.Scaling.SetInput(hand.RatioIndex, ratio);
            events.Add("console", $"{arm} scale factor {before:G4} -> {ratio:G4} ({hand.Scaling.Name}.ratio, clutch held)");
            return CommandResult.Ok($"{arm} scale factor {ratio:G4}");
        });
    }

    private WorkspaceView BuildWorkspace()
    {
        var arms = WorkspaceSampler.Sample(Robot, WorkspaceInterior, WorkspaceWalls);
        static double[] Metres(IReadOnlyList<Kinematics.Geometry.Vector3d> points) =>
            [.. points.SelectMany(p => new[] { Math.Round(p.X * 1e-3, 5), Math.Round(p.Y * 1e-3, 5), Math.Round(p.Z * 1e-3, 5) })];
        return new WorkspaceView([.. arms.Select(a => new ArmWorkspaceView(a.Arm, UrdfExport.ToolLinkName(a.Arm), Metres(a.Interior), Metres(a.Walls)))]);
    }
}
