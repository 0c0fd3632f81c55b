using System.Text.Json.Nodes;

namespace RobotControl.Definitions.Tests.Loading;

/// <summary>
/// The shipped robot files, and a temporary tree (robots/ next to copies of the component catalogues) for edited
/// copies, so a test can break one field of a good file.
/// </summary>
internal sealed class RobotFiles : IDisposable
{
    public RobotFiles()
    {
        Root = Path.Combine(Path.GetTempPath(), "robotcontrol-hardware-tests-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(Path.Combine(Root, "robots"));
        Directory.CreateDirectory(Path.Combine(Root, "components"));
        foreach (var catalogue in Directory.GetFiles(Path.Combine(HardwareDirectory, "components"), "*.json"))
        {
            File.Copy(catalogue, Path.Combine(Root, "components", Path.GetFileName(catalogue)));
        }
    }

    public static string HardwareDirectory { get; } = FindHardwareDirectory();

    public string Root { get; }

    public static string Shipped(string file) => Path.Combine(HardwareDirectory, "robots", file);

    public static JsonNode Json(string file) => JsonNode.Parse(File.ReadAllText(Shipped(file)))!;

    /// <summary>Writes <paramref name="json"/> as a robot file in the temporary tree and returns its full path.</summary>
    public string Write(JsonNode json, string name = "edited.json") => WriteText(json.ToJsonString(), name);

    public string WriteText(string text, string name = "edited.json")
    {
        var path = Path.Combine(Root, "robots", name);
        File.WriteAllText(path, text);
        return path;
    }

    /// <summary>Path of the temporary copy of a catalogue (to break it).</summary>
    public string Catalogue(string file) => Path.Combine(Root, "components", file);

    public void Dispose()
    {
        try
        {
            Directory.Delete(Root, recursive: true);
        }
        catch (IOException)
        {
            // A leftover temp directory is harmless.
        }
    }

    private static string FindHardwareDirectory()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            var candidate = Path.Combine(dir.FullName, "hardware");
            if (File.Exists(Path.Combine(candidate, "robots", "crb-1.0.json")))
            {
                return candidate;
            }
        }

        throw new InvalidOperationException("hardware/ not found above " + AppContext.BaseDirectory);
    }
}
