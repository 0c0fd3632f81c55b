using RobotControl.Bus.Client;
using RobotControl.Definitions.Model;

namespace RobotControl.WebConsole.BringUp;

/// <summary>What the bring-up console works on (<c>robotctl console --bring-up</c>).</summary>
/// <param name="RobotFile">The robot file as given (recorded in a new unit file).</param>
/// <param name="Robot">The robot file, loaded and checked.</param>
/// <param name="Unit">The unit's name.</param>
/// <param name="UnitPath">Its unit file, <c>&lt;units&gt;/&lt;name&gt;.json</c>.</param>
/// <param name="Transport">The bus, as given (<c>serial:...</c>).</param>
/// <param name="Open">Opens the bus at a baud rate (a step opens it when it starts and closes it when it ends).</param>
/// <param name="Time">The clock.</param>
public sealed record BringUpSetup(string RobotFile, RobotDefinition Robot, string Unit, string UnitPath, string Transport, Func<int, BusClient> Open, TimeProvider Time);
