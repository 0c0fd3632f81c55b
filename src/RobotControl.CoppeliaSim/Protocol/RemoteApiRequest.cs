namespace RobotControl.CoppeliaSim.Protocol;

/// <summary>
/// One request: <c>func</c>, <c>args</c>, <c>uuid</c>; on first contact also <c>ver</c>, <c>lang</c> and
/// <c>timeout</c> (seconds, the server's idea of how long it may wait on this client); <c>argsL</c> always.
/// </summary>
/// <param name="Func">Function name, e.g. <c>sim.getObject</c>, or <see cref="RemoteApiWords.Executed"/>.</param>
/// <param name="Args">Arguments: null, bool, integers, double, string, byte[], lists and string-keyed dictionaries of these.</param>
/// <param name="Uuid">The client's identifier.</param>
/// <param name="FirstContactTimeoutSeconds">Set on first contact (adds <c>ver</c>, <c>lang</c>, <c>timeout</c>); null afterwards.</param>
public sealed record RemoteApiRequest(string Func, IReadOnlyList<object?> Args, string Uuid, int? FirstContactTimeoutSeconds);
