using System.Globalization;

namespace RobotControl.Bus.Transports;

/// <summary>Which kind of byte link a transport string selects.</summary>
public enum LinkKind
{
    /// <summary><c>serial:/dev/ttyUSB0?baud=1000000</c>: a serial device.</summary>
    Serial,

    /// <summary><c>usb:0403:6001:&lt;serial&gt;</c>: a USB-serial adapter found by vendor, product and serial number.</summary>
    Usb,

    /// <summary><c>tcp:127.0.0.1:4000</c>: a serial-over-network bridge.</summary>
    Tcp,

    /// <summary><c>virtual:hardware/robots/lb-1.0.json</c>: the in-process virtual robot.</summary>
    Virtual,
}

/// <summary>Parity of a serial link.</summary>
public enum SerialParity
{
    /// <summary>No parity bit (8N1, the Dynamixel default).</summary>
    None,

    /// <summary>Even parity.</summary>
    Even,

    /// <summary>Odd parity.</summary>
    Odd,
}

/// <summary>Who switches an RS-485 transceiver between sending and receiving (half-duplex turn-around).</summary>
public enum Rs485DriverEnable
{
    /// <summary>The adapter does it by itself (FTDI USB-RS485 cables and most USB-RS485 adapters): nothing to do.</summary>
    Auto,

    /// <summary>The host asserts RTS while it sends (RTS wired to the transceiver's driver-enable).</summary>
    Rts,
}

/// <summary>
/// A parsed transport string: <c>kind:target?key=value&amp;...</c>. Options: <c>baud</c> (all kinds; default 1000000),
/// <c>parity</c> (none|even|odd), <c>rs485</c> (auto|rts: who drives the RS-485 driver-enable, see
/// <see cref="Rs485DriverEnable"/>), <c>seed</c> and <c>realtime</c> (virtual).
/// </summary>
public sealed record LinkUri
{
    /// <summary>Default bus speed.</summary>
    public const int DefaultBaud = 1_000_000;

    private LinkUri(LinkKind kind, string target, IReadOnlyDictionary<string, string> options)
    {
        Kind = kind;
        Target = target;
        Options = options;
    }

    /// <summary>The link kind.</summary>
    public LinkKind Kind { get; }

    /// <summary>Device path, <c>vendor:product[:serial]</c>, <c>host:port</c> or robot file, as written.</summary>
    public string Target { get; }

    /// <summary>The <c>?key=value</c> options (keys lower-case).</summary>
    public IReadOnlyDictionary<string, string> Options { get; }

    /// <summary>Bits per second (<c>baud</c> option).</summary>
    public int BaudRate => Options.TryGetValue("baud", out var b) ? int.Parse(b, CultureInfo.InvariantCulture) : DefaultBaud;

    /// <summary>Parity (<c>parity</c> option).</summary>
    public SerialParity Parity => Options.TryGetValue("parity", out var p) ? Enum.Parse<SerialParity>(p, ignoreCase: true) : SerialParity.None;

    /// <summary>Who drives the RS-485 driver-enable (<c>rs485</c> option; default <see cref="Rs485DriverEnable.Auto"/>).</summary>
    public Rs485DriverEnable Rs485 => Options.TryGetValue("rs485", out var v) ? Enum.Parse<Rs485DriverEnable>(v, ignoreCase: true) : Rs485DriverEnable.Auto;

    /// <summary>Parses a transport string.</summary>
    /// <exception cref="FormatException">The string is empty, names no known kind, or its target or options are malformed.</exception>
    public static LinkUri Parse(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        var colon = text.IndexOf(':', StringComparison.Ordinal);
        if (colon <= 0)
        {
            throw new FormatException($"transport '{text}': expected kind:target, e.g. serial:/dev/ttyUSB0?baud=1000000, usb:0403:6001:<serial>, tcp:127.0.0.1:4000, virtual:hardware/robots/lb-1.0.json");
        }

        var kindText = text[..colon].ToLowerInvariant();
        var kind = kindText switch
        {
            "serial" => LinkKind.Serial,
            "usb" => LinkKind.Usb,
            "tcp" => LinkKind.Tcp,
            "virtual" => LinkKind.Virtual,
            _ => throw new FormatException($"transport '{text}': unknown kind '{kindText}' (serial, usb, tcp, virtual)"),
        };
        var rest = text[(colon + 1)..];
        var query = rest.IndexOf('?', StringComparison.Ordinal);
        var target = query >= 0 ? rest[..query] : rest;
        var options = new Dictionary<string, string>(StringComparer.Ordinal);
        if (query >= 0)
        {
            foreach (var pair in rest[(query + 1)..].Split('&', StringSplitOptions.RemoveEmptyEntries))
            {
                var eq = pair.IndexOf('=', StringComparison.Ordinal);
                if (eq <= 0)
                {
                    throw new FormatException($"transport '{text}': option '{pair}' must be key=value");
                }

                options[pair[..eq].ToLowerInvariant()] = pair[(eq + 1)..];
            }
        }

        if (target.Length == 0)
        {
            throw new FormatException($"transport '{text}': the {kindText} target is empty");
        }

        var uri = new LinkUri(kind, target, options);
        uri.Validate(text);
        return uri;
    }

    /// <summary>Splits a TCP target into host and port.</summary>
    public (string Host, int Port) TcpEndpoint()
    {
        var i = Target.LastIndexOf(':');
        return (Target[..i], int.Parse(Target[(i + 1)..], CultureInfo.InvariantCulture));
    }

    /// <summary>Splits a USB target into vendor ID, product ID and (optional) serial number.</summary>
    public (ushort Vendor, ushort Product, string? Serial) UsbIds()
    {
        var parts = Target.Split(':', 3);
        return (ushort.Parse(parts[0], NumberStyles.HexNumber, CultureInfo.InvariantCulture),
            ushort.Parse(parts[1], NumberStyles.HexNumber, CultureInfo.InvariantCulture),
            parts.Length > 2 && parts[2].Length > 0 ? parts[2] : null);
    }

    /// <inheritdoc />
    public override string ToString() =>
        $"{Kind.ToString().ToLowerInvariant()}:{Target}" + (Options.Count == 0 ? string.Empty : "?" + string.Join('&', Options.Select(kv => $"{kv.Key}={kv.Value}")));

    private void Validate(string text)
    {
        foreach (var key in Options.Keys)
        {
            if (key is not ("baud" or "parity" or "rs485" or "seed" or "realtime"))
            {
                throw new FormatException($"transport '{text}': unknown option '{key}' (baud, parity, rs485, seed, realtime)");
            }
        }

        if (Options.TryGetValue("baud", out var baud) && (!int.TryParse(baud, NumberStyles.None, CultureInfo.InvariantCulture, out var b) || b < 300 || b > 20_000_000))
        {
            throw new FormatException($"transport '{text}': baud '{baud}' must be a whole number from 300 to 20000000");
        }

        if (Options.TryGetValue("parity", out var parity) && !Enum.TryParse<SerialParity>(parity, ignoreCase: true, out _))
        {
            throw new FormatException($"transport '{text}': parity '{parity}' must be none, even or odd");
        }

        if (Options.TryGetValue("rs485", out var rs) && !(rs.Equals("auto", StringComparison.OrdinalIgnoreCase) || rs.Equals("rts", StringComparison.OrdinalIgnoreCase)))
        {
            throw new FormatException($"transport '{text}': rs485 '{rs}' must be auto (the adapter switches direction itself, the default) or rts (the host raises RTS while it sends)");
        }

        switch (Kind)
        {
            case LinkKind.Tcp:
                var i = Target.LastIndexOf(':');
                if (i <= 0 || !int.TryParse(Target[(i + 1)..], NumberStyles.None, CultureInfo.InvariantCulture, out var port) || port is < 1 or > 65535)
                {
                    throw new FormatException($"transport '{text}': expected tcp:host:port with a port from 1 to 65535");
                }

                break;
            case LinkKind.Usb:
                var parts = Target.Split(':', 3);
                if (parts.Length < 2 || !IsHex16(parts[0]) || !IsHex16(parts[1]))
                {
                    throw new FormatException($"transport '{text}': expected usb:<vendor hex>:<product hex>[:<serial>], e.g. usb:0403:6001:A50285BI");
                }

                break;
        }
    }

    private static bool IsHex16(string s) => s.Length is > 0 and <= 4 && ushort.TryParse(s, NumberStyles.HexNumber, CultureInfo.InvariantCulture, out _);
}
