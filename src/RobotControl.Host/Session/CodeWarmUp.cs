using System.Reflection;
using System.Runtime.CompilerServices;
using RobotControl.Bus.Client;
using RobotControl.Definitions.Model;
using RobotControl.Host.Safety;
using RobotControl.Modules;
using RobotControl.Plugins.Sdk;
using RobotControl.Robot.Bus;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.Loop;

namespace RobotControl.Host.Session;

/// <summary>
/// Compiles, before the modules are armed, the code the first ticks would otherwise compile on the loop thread: every
/// method and constructor of the graph's plug-in types and of the types the cycle runs through (program, loop, robot,
/// safety, a trip's path). The first tick of a graph left to the JIT took 9.6–10.6 ms in a fresh <c>robotctl run</c>
/// process, 1.8–3.0 ms with this (3,064 methods and constructors in 200–255 ms, before arming; docs/perf/realtime.md).
/// Generic definitions and abstract methods are skipped; a method that cannot be prepared is left to the JIT.
/// </summary>
internal static class CodeWarmUp
{
    private const BindingFlags Declared = BindingFlags.DeclaredOnly | BindingFlags.Instance | BindingFlags.Static | BindingFlags.Public | BindingFlags.NonPublic;

    /// <summary>
    /// The types a tick and a bus cycle run through: every type of the graph's plug-in assemblies and of the kinematics
    /// they use, of the plug-in SDK, the graph runtime, the robot layer, the modules' model and the bus client, plus the loop, the safety
    /// layer with its limits and names from the robot model (a trip's path too: it compiled 14 methods, 1.1–1.6 ms, on the
    /// bus thread at the first trip) and the stop's read-back.
    /// </summary>
    public static IEnumerable<Type> CycleTypes(GraphProgram program)
    {
        ArgumentNullException.ThrowIfNull(program);
        var assemblies = program.Order.Select(p => p.GetType().Assembly)
            .Concat([typeof(Plugin).Assembly, typeof(GraphProgram).Assembly, typeof(BusRobot).Assembly, typeof(HardwareErrors).Assembly, typeof(BusClient).Assembly])
            .Distinct()
            .ToList();
        var kinematics = assemblies.SelectMany(a => a.GetReferencedAssemblies()).Where(n => n.Name == "RobotControl.Kinematics").Select(Assembly.Load);
        return assemblies.Concat(kinematics).Distinct().SelectMany(a => a.GetTypes())
            .Concat(typeof(SafetySupervisor).Assembly.GetTypes().Where(t => t.Namespace == typeof(SafetySupervisor).Namespace))
            .Concat([typeof(ControlLoop), typeof(StopCheck), typeof(SafetyLimits), typeof(MotorSafetyLimits), typeof(SafetyNames), typeof(MotorName)]);
    }

    /// <summary>
    /// Prepares every method and constructor of <paramref name="types"/> and of their nested types; returns how many were
    /// prepared. Under tiered compilation this compiles the quick (tier-0) code of each; interface implementations are
    /// left to their first call all the same (measured: the robot port's reads and writes, on the loop's first tick).
    /// </summary>
    public static int Prepare(IEnumerable<Type> types)
    {
        ArgumentNullException.ThrowIfNull(types);
        var prepared = 0;
        var seen = new HashSet<Type>();
        var pending = new Stack<Type>(types);
        while (pending.TryPop(out var type))
        {
            if (!seen.Add(type) || type.ContainsGenericParameters)
            {
                continue;
            }

            foreach (var nested in type.GetNestedTypes(Declared))
            {
                pending.Push(nested);
            }

            // Constructors too (a tick builds value types: tick contexts, IK targets, samples); not type initializers,
            // which would run a type's static set-up ahead of its first use.
            foreach (var method in type.GetMethods(Declared).Cast<MethodBase>().Concat(type.GetConstructors(Declared & ~BindingFlags.Static)))
            {
                if (method.IsAbstract || method.ContainsGenericParameters)
                {
                    continue;
                }

                try
                {
                    RuntimeHelpers.PrepareMethod(method.MethodHandle);
                    prepared++;
                }
                catch (Exception ex) when (ex is ArgumentException or NotSupportedException or TypeLoadException or BadImageFormatException or InvalidOperationException)
                {
                    // Left to the JIT on first call (e.g. a method with a native or unusual signature).
                }
            }
        }

        return prepared;
    }
}
