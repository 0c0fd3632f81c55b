using System.Text.Json;
using Microsoft.AspNetCore.Http;

namespace RobotControl.WebConsole.Server;

/// <summary>Request bodies of the API.</summary>
internal static class ApiBodies
{
    /// <summary>The largest request body the console reads (a graph is a few kB).</summary>
    public const long MaxBytes = 4 * 1024 * 1024;

    /// <summary>Reads a JSON body as <typeparamref name="T"/>; null and the 400 message when it is missing or malformed.</summary>
    public static async Task<(T? Body, string? Problem)> Read<T>(HttpRequest request, string what)
        where T : class
    {
        try
        {
            var body = await JsonSerializer.DeserializeAsync<T>(request.Body, ConsoleJson.Options, request.HttpContext.RequestAborted).ConfigureAwait(false);
            return body is null ? (null, $"{what}: the request needs a JSON body") : (body, null);
        }
        catch (JsonException ex)
        {
            return (null, $"{what}: malformed JSON body ({ex.Message.Split(". ")[0]})");
        }
        catch (BadHttpRequestException ex) when (ex.StatusCode == StatusCodes.Status413PayloadTooLarge)
        {
            return (null, $"{what}: the body is over {MaxBytes / (1024 * 1024)} MiB");
        }
    }
}

/// <summary>A number, e.g. <c>{"value": 12.5}</c>.</summary>
/// <param name="Value">The value.</param>
internal sealed record ValueBody(double? Value);

/// <summary>A jog speed, <c>{"degPerS": 10}</c>.</summary>
/// <param name="DegPerS">Speed at the axis output, deg/s.</param>
internal sealed record JogBody(double? DegPerS);

/// <summary>A setpoint, <c>{"deg": 10}</c>.</summary>
/// <param name="Deg">Axis output angle, degrees.</param>
internal sealed record SetpointBody(double? Deg);

/// <summary>Body of <c>POST /api/pedal</c>.</summary>
/// <param name="Down">True: pedal down (the robot moves); false: up (it holds).</param>
internal sealed record PedalBody(bool? Down);

/// <summary>The record button, <c>{"on": true}</c>: start (true) or stop recording the session.</summary>
/// <param name="On">True: start a recording; false: stop it.</param>
internal sealed record RecordBody(bool? On);

/// <summary>Torque, <c>{"on": true}</c>.</summary>
/// <param name="On">True: drive the motors.</param>
internal sealed record TorqueBody(bool? On);

/// <summary>A name, <c>{"name": "right shoulder"}</c>.</summary>
/// <param name="Name">The name.</param>
internal sealed record NameBody(string? Name);
