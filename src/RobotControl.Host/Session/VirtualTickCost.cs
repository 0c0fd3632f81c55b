namespace RobotControl.Host.Session;

/// <summary>What a tick costs the loop on the virtual schedule (<see cref="VirtualSchedule"/>).</summary>
public enum VirtualTickCost
{
    /// <summary>
    /// The tick's CPU time on the schedule's thread (<see cref="ThreadCpuClock"/>, without compiling) counts against its
    /// period, as on a loop thread: a graph too slow for its rate misses its deadlines on the virtual robot. The
    /// measurement is the machine's: on a virtual machine the thread's CPU time also holds time its virtual CPU did
    /// not run (measured here: a 6 µs tick charged 6 ms under load), so such a run is not exactly reproducible.
    /// </summary>
    Measured,

    /// <summary>
    /// Ticks take no loop time: the run is exactly reproducible (the same robot, graph, faults and seed give the same
    /// run on any machine, however loaded), and no deadline is missed. For tests and comparisons; the benchmarks
    /// measure the graph's speed.
    /// </summary>
    Free,
}
