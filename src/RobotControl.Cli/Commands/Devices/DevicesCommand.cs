using System.CommandLine;
using System.Globalization;
using RobotControl.Plugins.Touch.OpenHaptics;

namespace RobotControl.Cli.Commands.Devices;

/// <summary>
/// <c>robotctl devices [--device name]... [--library-path path]</c>: the Geomagic Touch devices the OpenHaptics
/// library can open, with serial, calibration state and nominal forces. Exit 0 when at least one opens, 1 when none
/// does, 2 when the library is not installed.
/// </summary>
internal sealed class DevicesCommand : ICliCommand
{
    /// <inheritdoc />
    public Command Build()
    {
        var devices = new Option<string[]>("--device") { Description = "A device name as configured in Touch Setup (repeat for several; default: the default device)", AllowMultipleArgumentsPerToken = false };
        var library = new Option<string?>("--library-path") { Description = "The HD library (libHD.so / HD.dll) or its folder (default: LD_LIBRARY_PATH, then the system's library path)" };
        var command = new Command("devices", "List the Geomagic Touch devices OpenHaptics can open: name, serial, calibration, nominal forces.");
        command.Options.Add(devices);
        command.Options.Add(library);
        command.SetAction(parse => Run(
            parse.GetValue(devices) ?? [],
            parse.GetValue(library) ?? "",
            parse.InvocationConfiguration.Output,
            parse.InvocationConfiguration.Error));
        return command;
    }

    /// <summary>Runs the command; returns the exit code.</summary>
    internal static int Run(IReadOnlyList<string> names, string libraryPath, TextWriter output, TextWriter error)
    {
        IReadOnlyList<TouchProbe> probes;
        try
        {
            probes = TouchDevices.Probe(libraryPath, names.Count == 0 ? [""] : names);
        }
        catch (TouchDeviceException ex)
        {
            error.WriteLine(ex.Message);
            return 2;
        }

        var c = CultureInfo.InvariantCulture;
        output.WriteLine($"OpenHaptics library: {HdLibrary.LoadedFrom}");
        foreach (var p in probes)
        {
            var name = p.Name.Length == 0 ? "(default device)" : p.Name;
            output.WriteLine(p.Info is { } i
                ? string.Create(c, $"{name}: {i.Model}, serial {i.Serial}, calibration {i.CalibrationText}, nominal max force {i.NominalMaxForceN:0.###} N, continuous {i.NominalMaxContinuousForceN:0.###} N")
                : $"{name}: cannot open: {p.Error}");
        }

        var opened = probes.Count(p => p.Info is not null);
        output.WriteLine($"{opened} of {probes.Count} device(s) opened");
        return opened > 0 ? 0 : 1;
    }
}
