using RobotControl.Plugins.Sdk;
using RobotControl.Runtime.Graph;

namespace RobotControl.TestSupport;

public static class Ticks
{
    public static TickContext At(long index) =>
        new(index, index * TimeSpan.TicksPerMillisecond, TimeSpan.FromMilliseconds(index), TimeSpan.FromMilliseconds(1));

    public static void Run(GraphProgram program, int ticks)
    {
        program.Start(At(0));
        for (var i = 0; i < ticks; i++)
        {
            program.Tick(At(i));
        }
    }
}
