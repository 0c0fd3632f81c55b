using System.Text.Json;
using System.Text.Json.Serialization;

namespace RobotControl.WebConsole.Server;

/// <summary>The API's JSON settings: camelCase, NaN and infinities as strings (a value not read yet is NaN).</summary>
internal static class ConsoleJson
{
    /// <summary>The options.</summary>
    public static JsonSerializerOptions Options { get; } = new(JsonSerializerDefaults.Web)
    {
        Encoder = System.Text.Encodings.Web.JavaScriptEncoder.UnsafeRelaxedJsonEscaping,
        NumberHandling = JsonNumberHandling.AllowNamedFloatingPointLiterals,
        UnmappedMemberHandling = JsonUnmappedMemberHandling.Disallow,
        Converters = { new JsonStringEnumConverter(JsonNamingPolicy.CamelCase) },
    };
}
