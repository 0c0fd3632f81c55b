using System.Net;
using System.Text;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Http.HttpResults;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Server;

/// <summary>
/// Every operator command the console answers goes into the session's recording (<see cref="IConsoleSession.NoteCommand"/>,
/// the <c>/operator/commands</c> topic, docs/recording.md): who (the console's name, its role, its address) and what
/// (the request, its body, the answer). The actions, the operator role's claims and releases, and the emergency stop,
/// which is noted after it has been answered: noting never comes before stopping.
/// </summary>
internal static class CommandWitness
{
    /// <summary>Longest body quoted in a note; a longer one is cut and says so.</summary>
    private const int MaxBody = 200;

    /// <summary>Notes every request <paramref name="builder"/>'s endpoints answer.</summary>
    public static TBuilder Witnessed<TBuilder>(this TBuilder builder, IConsoleSession session, OperatorRole role)
        where TBuilder : IEndpointConventionBuilder
    {
        builder.AddEndpointFilter(async (context, next) =>
        {
            var http = context.HttpContext;
            http.Request.EnableBuffering(); // the handler reads the body; the note reads it again after
            var who = Who(http, role); // the role before the command: a claim is made by a watching console
            var result = await next(context).ConfigureAwait(false);
            session.NoteCommand(who, await What(http, result).ConfigureAwait(false));
            return result;
        });
        return builder;
    }

    /// <summary>The console that sent <paramref name="http"/>: its name, its role, its address.</summary>
    public static string Who(HttpContext http, OperatorRole role)
    {
        var client = ApiEndpoints.ClientOf(http);
        var operating = client is not null && role.Holder == client;
        return $"console {client ?? "(unnamed)"} ({(operating ? "operator" : "watching")}) at {http.Connection.RemoteIpAddress ?? IPAddress.None}";
    }

    /// <summary>The request, its body and the answer, in one line.</summary>
    public static async Task<string> What(HttpContext http, object? result)
    {
        var request = http.Request;
        var body = string.Empty;
        if (request.Body.CanSeek)
        {
            request.Body.Position = 0;
            var buffer = new byte[MaxBody + 1];
            var read = 0;
            for (int n; read < buffer.Length && (n = await request.Body.ReadAsync(buffer.AsMemory(read)).ConfigureAwait(false)) > 0;)
            {
                read += n;
            }

            body = Encoding.UTF8.GetString(buffer, 0, Math.Min(read, MaxBody)).ReplaceLineEndings(" ") + (read > MaxBody ? "...(cut)" : string.Empty);
        }

        return $"{request.Method} {request.Path}{(body.Length == 0 ? string.Empty : " " + body)} -> {Answer(result)}";
    }

    /// <summary>The answer's status and line.</summary>
    public static string Answer(object? result)
    {
        var status = result is IStatusCodeHttpResult { StatusCode: { } code } ? code : StatusCodes.Status200OK;
        var line = result switch
        {
            IValueHttpResult { Value: CommandResult command } => command.Message,
            IValueHttpResult { Value: ApiError error } => error.Error,
            _ => string.Empty,
        };
        return line.Length == 0 ? $"{status}" : $"{status} {line}";
    }
}
