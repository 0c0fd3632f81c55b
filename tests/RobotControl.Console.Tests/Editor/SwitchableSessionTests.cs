using System.Reflection;
using RobotControl.WebConsole.Editor;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Tests.Editor;

public sealed class SwitchableSessionTests
{
    /// <summary>A console session that only records which of its members were called.</summary>
    public class RecordingSession : DispatchProxy
    {
        public List<string> Calls { get; } = [];

        public static (IConsoleSession Session, RecordingSession Record) Create()
        {
            var session = Create<IConsoleSession, RecordingSession>();
            return (session, (RecordingSession)(object)session);
        }

        protected override object? Invoke(MethodInfo? targetMethod, object?[]? args)
        {
            Calls.Add(targetMethod!.Name);
            return null;
        }
    }

    [Fact]
    public void Once_the_console_closes_no_graph_replaces_the_one_closing_and_the_newcomer_is_disposed()
    {
        var (first, firstCalls) = RecordingSession.Create();
        var switchable = new SwitchableSession(first);
        _ = switchable.Close();
        Assert.Equal(["Close"], firstCalls.Calls);

        var (next, nextCalls) = RecordingSession.Create();
        var refused = Assert.Throws<InvalidOperationException>(() => switchable.Replace(next));

        Assert.Equal("the console is stopping: no graph starts now", refused.Message);
        Assert.Equal(["Dispose"], nextCalls.Calls); // its motors go off with it; nothing of it runs
        Assert.Same(first, switchable.Current);
    }

    [Fact]
    public void Before_the_console_closes_a_graph_replaces_the_one_running()
    {
        var (first, _) = RecordingSession.Create();
        var switchable = new SwitchableSession(first);
        var (next, nextCalls) = RecordingSession.Create();

        Assert.Same(first, switchable.Replace(next));
        Assert.Same(next, switchable.Current);
        Assert.Empty(nextCalls.Calls);
    }
}
