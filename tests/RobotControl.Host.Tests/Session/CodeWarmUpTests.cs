using RobotControl.Host.Session;

namespace RobotControl.Host.Tests.Session;

/// <summary>What is compiled before arming: the graph's plug-in types and the cycle's, concrete methods and constructors only.</summary>
public sealed class CodeWarmUpTests
{
    [Fact]
    public void Concrete_methods_and_constructors_are_prepared_and_generic_definitions_and_abstract_ones_skipped()
    {
        // Sample: Twice, Nested.Thrice (a nested type is included); skipped: Any<T> (generic), Shape.Area (abstract).
        Assert.Equal(2, CodeWarmUp.Prepare([typeof(Sample)]));
        Assert.Equal(2, CodeWarmUp.Prepare([typeof(Shape)])); // Shape.Name and the constructor; Area is abstract
        Assert.Equal(2, CodeWarmUp.Prepare([typeof(Point)])); // the constructor a tick would call, and X
    }

    [Fact]
    public void The_cycle_types_of_the_teleop_graph_include_every_plug_in_type_it_runs_and_the_loop_and_supervisor()
    {
        using var session = RobotSession.Open(new SessionOptions { GraphPath = Graphs.Path("teleop-lb.json"), Virtual = true }, TestPlugins.Catalog());
        var types = CodeWarmUp.CycleTypes(session.Graph.Program).ToHashSet();
        Assert.All(session.Graph.Program.Order, p => Assert.Contains(p.GetType(), types));
        Assert.Contains(typeof(Runtime.Loop.ControlLoop), types);
        Assert.Contains(typeof(Host.Safety.SafetySupervisor), types);
        Assert.Contains(typeof(Definitions.Model.SafetyLimits), types); // a trip's path
        Assert.Contains(typeof(Definitions.Model.MotorName), types); // a trip names its motor
        Assert.Contains(typeof(Modules.HardwareErrors), types);
        Assert.Contains(types, t => t.Assembly.GetName().Name == "RobotControl.Kinematics");
    }

    private static class Sample
    {
        public static int Twice(int x) => 2 * x;

        public static T Any<T>(T x) => x;

        public static class Nested
        {
            public static int Thrice(int x) => 3 * x;
        }
    }

    private readonly struct Point(double x)
    {
        public double X { get; } = x;
    }

    private abstract class Shape
    {
        public abstract double Area();

        public string Name() => GetType().Name;
    }
}
