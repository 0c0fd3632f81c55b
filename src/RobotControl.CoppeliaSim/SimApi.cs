using System.Globalization;

namespace RobotControl.CoppeliaSim;

/// <summary>Typed calls of CoppeliaSim's <c>sim</c> module the bridge needs, over a <see cref="RemoteApiClient"/>.</summary>
public sealed class SimApi
{
    private static readonly Dictionary<string, object?> NoErrorOption = new(StringComparer.Ordinal) { ["noError"] = true };

    /// <summary>Wraps <paramref name="client"/>.</summary>
    public SimApi(RemoteApiClient client)
    {
        ArgumentNullException.ThrowIfNull(client);
        Client = client;
    }

    /// <summary>The client the calls go through.</summary>
    public RemoteApiClient Client { get; }

    /// <summary><c>zmqRemoteApi.require("sim")</c>: loads the sim module for this client (first call of a session).</summary>
    public void RequireSim() => Client.Call("zmqRemoteApi.require", "sim");

    /// <summary><c>sim.getObject(path)</c>; with <paramref name="noError"/> a missing object gives -1 instead of an error.</summary>
    public long GetObject(string path, bool noError = false)
    {
        ArgumentException.ThrowIfNullOrEmpty(path);
        var ret = noError ? Client.Call("sim.getObject", path, NoErrorOption) : Client.Call("sim.getObject", path);
        return Convert.ToInt64(First(ret, "sim.getObject"), CultureInfo.InvariantCulture);
    }

    /// <summary><c>sim.setJointPosition(handle, rad)</c>: places a joint (kinematic mode).</summary>
    public void SetJointPosition(long handle, double positionRad) => Client.Call("sim.setJointPosition", handle, positionRad);

    /// <summary><c>sim.setJointTargetPosition(handle, rad)</c>: the joint's controller target (dynamic mode).</summary>
    public void SetJointTargetPosition(long handle, double positionRad) => Client.Call("sim.setJointTargetPosition", handle, positionRad);

    /// <summary><c>sim.getJointPosition(handle)</c>, radians.</summary>
    public double GetJointPosition(long handle) =>
        Convert.ToDouble(First(Client.Call("sim.getJointPosition", handle), "sim.getJointPosition"), CultureInfo.InvariantCulture);

    /// <summary><c>sim.setStepping(on)</c>: in stepping mode the simulation advances only when this client calls <see cref="Step"/>.</summary>
    public void SetStepping(bool enabled) => Client.Call("sim.setStepping", enabled);

    /// <summary><c>sim.step()</c>: one simulation step (the server answers <c>_*wait*_</c> until it is done).</summary>
    public void Step() => Client.Call("sim.step");

    /// <summary><c>sim.startSimulation()</c>.</summary>
    public void StartSimulation() => Client.Call("sim.startSimulation");

    /// <summary><c>sim.stopSimulation()</c>.</summary>
    public void StopSimulation() => Client.Call("sim.stopSimulation");

    private static object First(IReadOnlyList<object?> ret, string func) =>
        ret.Count > 0 && ret[0] is { } value ? value : throw new CoppeliaSimServerException($"{func}: the server returned no value");
}
