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
}
