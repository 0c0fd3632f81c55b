namespace RobotControl.CoppeliaSim.Protocol;

/// <summary>One reply: results (<c>ret</c>), an error (<c>err</c>), or a wait/repeat/end/callback request (<c>func</c> + <c>args</c>).</summary>
/// <param name="Ret">Return values when the call completed.</param>
/// <param name="Error">The server's error message (unescaped), or null.</param>
/// <param name="Func">A special word or callback name, or null.</param>
/// <param name="Args">Arguments of a callback.</param>
public sealed record RemoteApiReply(IReadOnlyList<object?> Ret, string? Error, string? Func, IReadOnlyList<object?> Args);
