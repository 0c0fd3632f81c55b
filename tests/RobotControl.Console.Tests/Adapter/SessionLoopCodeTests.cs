using System.Reflection;
using RobotControl.Bus.Client;
using RobotControl.Bus.Transports;
using RobotControl.Simulation;
using RobotControl.WebConsole.Adapter;

namespace RobotControl.WebConsole.Tests.Adapter;

/// <summary>
/// The console runs the robot's one bus loop (the session layer's bus thread, or its virtual schedule): it keeps no
/// bus client, transport or simulator of its own and runs no bus cycle itself.
/// </summary>
public sealed class SessionLoopCodeTests
{
    [Fact]
    public void The_console_session_holds_no_bus_client_transport_or_simulator_of_its_own()
    {
        var fields = typeof(LiveSession).GetFields(BindingFlags.Instance | BindingFlags.NonPublic | BindingFlags.Public);
        var own = fields.Where(f => typeof(BusClient).IsAssignableFrom(f.FieldType) || typeof(IByteLink).IsAssignableFrom(f.FieldType) || typeof(VirtualRobot).IsAssignableFrom(f.FieldType)).Select(f => f.Name).ToList();

        Assert.NotEmpty(fields);
        Assert.True(own.Count == 0, $"the console keeps bus parts of its own: {string.Join(", ", own)}");
        Assert.Null(typeof(LiveSession).GetMethod("RunRealTime", BindingFlags.Instance | BindingFlags.NonPublic)?.GetCustomAttribute<System.Runtime.CompilerServices.MethodImplAttribute>());
    }

    [Fact]
    public void No_part_of_the_live_session_holds_a_bus_client_transport_or_simulator_of_its_own()
    {
        var parts = typeof(LiveSession).Assembly.GetTypes().Where(t => t.Namespace == typeof(LiveSession).Namespace && !t.IsDefined(typeof(System.Runtime.CompilerServices.CompilerGeneratedAttribute), false)).ToList();
        var own = parts.SelectMany(t => t.GetFields(BindingFlags.Instance | BindingFlags.NonPublic | BindingFlags.Public).Select(f => (Type: t, Field: f)))
            .Where(x => typeof(BusClient).IsAssignableFrom(x.Field.FieldType) || typeof(IByteLink).IsAssignableFrom(x.Field.FieldType) || typeof(VirtualRobot).IsAssignableFrom(x.Field.FieldType))
            .Select(x => $"{x.Type.Name}.{x.Field.Name}").ToList();

        Assert.Contains(typeof(StatusPublisher), parts);
        Assert.True(own.Count == 0, $"the console keeps bus parts of its own: {string.Join(", ", own)}");
    }
}
