using System.Diagnostics;
using RobotControl.CoppeliaSim.Protocol;

namespace RobotControl.CoppeliaSim.Tests;

public sealed class RemoteApiClientTests
{
    private static readonly string[] Joints = ["/LB1/right_elbow", "/LB1/left_elbow"];

    [Fact]
    public void Typed_calls_reach_the_server_and_return_its_values()
    {
        using var server = new FakeCoppeliaSim(Joints);
        using var client = new RemoteApiClient(server.Endpoint, TimeSpan.FromSeconds(2));
        var sim = new SimApi(client);
        sim.RequireSim();
        var elbow = sim.GetObject("/LB1/right_elbow");
        Assert.Equal(-1, sim.GetObject("/LB1/nothing", noError: true));
        sim.SetJointPosition(elbow, 0.75);
        Assert.Equal(0.75, sim.GetJointPosition(elbow));
        Assert.Equal(0.75, server.Position("/LB1/right_elbow"));
        sim.SetStepping(true);
        sim.StartSimulation();
        Assert.True(server.Stepping);
        Assert.True(server.SimulationRunning);
        sim.StopSimulation();
        Assert.False(server.SimulationRunning);
    }

    [Fact]
    public void First_request_carries_version_language_and_timeout_and_later_ones_do_not()
    {
        using var server = new FakeCoppeliaSim(Joints);
        using var client = new RemoteApiClient(server.Endpoint, TimeSpan.FromSeconds(3));
        var sim = new SimApi(client);
        sim.RequireSim();
        sim.GetObject("/LB1/left_elbow");
        var requests = server.RawRequests.ToArray();
        Assert.Equal(2L, requests[0]["ver"]);
        Assert.Equal("csharp", requests[0]["lang"]);
        Assert.Equal(3L, requests[0]["timeout"]);
        Assert.Equal(client.Uuid, requests[0]["uuid"]);
        Assert.False(requests[1].ContainsKey("ver"));
        Assert.Equal(client.Uuid, requests[1]["uuid"]);
        Assert.Equal(1L, requests[1]["argsL"]);
    }

    [Fact]
    public void Step_answers_executed_to_every_wait_until_the_result_comes()
    {
        using var server = new FakeCoppeliaSim(Joints) { WaitsPerStep = 3 };
        using var client = new RemoteApiClient(server.Endpoint, TimeSpan.FromSeconds(2));
        new SimApi(client).Step();
        Assert.Equal(1, server.Steps);
        Assert.Equal(["sim.step", RemoteApiWords.Executed, RemoteApiWords.Executed, RemoteApiWords.Executed], server.Requests.Select(r => r.Func));
        Assert.All(server.Requests.Skip(1), r => Assert.Empty(r.Args));
    }

    [Fact]
    public void Repeat_resends_the_same_request()
    {
        using var server = new FakeCoppeliaSim(Joints);
        using var client = new RemoteApiClient(server.Endpoint, TimeSpan.FromSeconds(2));
        var sim = new SimApi(client);
        var handle = sim.GetObject("/LB1/right_elbow");
        server.SetPosition("/LB1/right_elbow", -0.25);
        server.RepeatNext(2);
        Assert.Equal(-0.25, sim.GetJointPosition(handle));
        var last = server.Requests.TakeLast(3).ToArray();
        Assert.All(last, r => Assert.Equal("sim.getJointPosition", r.Func));
        Assert.All(last, r => Assert.Equal(handle, r.Args[0]));
    }

    [Fact]
    public void Callback_runs_the_registered_handler_and_sends_its_results()
    {
        using var server = new FakeCoppeliaSim(Joints);
        using var client = new RemoteApiClient(server.Endpoint, TimeSpan.FromSeconds(2));
        client.RegisterCallback("myCallback", args => [(long)args[0]! * 2]);
        var ret = client.Call("test.callback");
        Assert.Equal("called back", ret[0]);
        var executed = server.Requests.Last();
        Assert.Equal(RemoteApiWords.Executed, executed.Func);
        Assert.Equal(42L, executed.Args[0]);
    }

    [Fact]
    public void End_reply_ends_the_session_and_the_next_call_connects_again()
    {
        using var server = new FakeCoppeliaSim(Joints);
        using var client = new RemoteApiClient(server.Endpoint, TimeSpan.FromSeconds(2));
        var ex = Assert.Throws<CoppeliaSimConnectionException>(() => client.Call("test.end"));
        Assert.Equal($"test.end: the server ended the session ({server.Endpoint})", ex.Message);
        Assert.Equal(-1, new SimApi(client).GetObject("/LB1/missing", noError: true));
        Assert.Equal(2, client.Connections);
    }

    [Fact]
    public void Server_error_surfaces_with_the_servers_message()
    {
        using var server = new FakeCoppeliaSim(Joints);
        using var client = new RemoteApiClient(server.Endpoint, TimeSpan.FromSeconds(2));
        var ex = Assert.Throws<CoppeliaSimServerException>(() => new SimApi(client).GetObject("/LB1/missing"));
        Assert.Equal("sim.getObject: Object does not exist.\n\t(in function 'sim.getObject')", ex.Message);
        Assert.Equal(1, client.Connections); // an error reply leaves the socket usable
        Assert.Equal(-1, new SimApi(client).GetObject("/LB1/missing", noError: true));
    }

    [Fact]
    public void Server_that_stops_answering_times_out_and_a_new_socket_reaches_the_restarted_server()
    {
        var server = new FakeCoppeliaSim(Joints);
        try
        {
            using var client = new RemoteApiClient(server.Endpoint, TimeSpan.FromMilliseconds(1000));
            var sim = new SimApi(client);
            var handle = sim.GetObject("/LB1/right_elbow");
            server.StopAnswering();
            var watch = Stopwatch.StartNew();
            Assert.Throws<CoppeliaSimConnectionException>(() => sim.GetJointPosition(handle));
            Assert.InRange(watch.ElapsedMilliseconds, 950, 5000);
            server.Kill();
            Assert.Throws<CoppeliaSimConnectionException>(() => sim.GetJointPosition(handle)); // nobody there
            server.Start();
            server.SetPosition("/LB1/right_elbow", 1.5);
            Assert.Equal(1.5, sim.GetJointPosition(handle));
            Assert.Equal(3, client.Connections);
        }
        finally
        {
            server.Dispose();
        }
    }

    [Fact]
    public void Backoff_doubles_to_its_maximum_and_resets()
    {
        var backoff = new Backoff(TimeSpan.FromMilliseconds(50), TimeSpan.FromMilliseconds(300));
        Assert.Equal([50, 100, 200, 300, 300], Enumerable.Range(0, 5).Select(_ => backoff.NextDelay().TotalMilliseconds));
        backoff.Reset();
        Assert.Equal(50, backoff.NextDelay().TotalMilliseconds);
    }
}
