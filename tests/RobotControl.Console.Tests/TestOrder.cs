// The console collections each run a virtual robot in real time plus headless Chromium: one at a time, so that two of
// them never share the (two-core) machine with each other.
[assembly: CollectionBehavior(DisableTestParallelization = true)]
