namespace RobotControl.Runtime.Graph;

/// <summary>Splits <c>instance.port</c> signal names (the instance is everything before the first dot).</summary>
internal static class SignalName
{
    public static bool TrySplit(string signal, out string instance, out string port)
    {
        var dot = signal.IndexOf('.', StringComparison.Ordinal);
        if (dot <= 0 || dot == signal.Length - 1)
        {
            instance = port = "";
            return false;
        }

        instance = signal[..dot];
        port = signal[(dot + 1)..];
        return true;
    }

    public static string Join(string instance, string port) => instance + "." + port;
}
