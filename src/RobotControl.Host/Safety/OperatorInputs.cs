using RobotControl.Definitions.Model;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Control;

namespace RobotControl.Host.Safety;

/// <summary>
/// What the graph reports about the operator, as the loop's thread writes it every tick: when the loop last ticked
/// (the loop's own deadline), how old the data driving each arm is (the master timeout; NaN counts as too old, 0
/// before any report: no device, never stale), the hand's speed at each device (a jump beyond the limit asks the robot
/// to hold at once, from this thread, and is counted for the supervisor's check to record), the teleoperation pedal and
/// the emergency-stop pedal or button. The supervisor's checks read it on the bus thread.
/// </summary>
[WrittenBy(RobotThread.Loop)]
internal sealed class OperatorInputs
{
    private readonly double[] _ageMs;
    private readonly double _speedLimit;
    private readonly Action _hold;
    private readonly TimeProvider _time;
    private long _lastTick;
    private volatile int _pedal;
    private volatile int _emergencyStop;
    private long _jumps;
    private int _jumpArm;
    private double _jumpSpeed;

    /// <param name="arms">Arms reported.</param>
    /// <param name="speedLimitMmPerS">The fastest a hand moves (<see cref="SafetyLimits.MasterSpeedMaxMmPerS"/>).</param>
    /// <param name="hold">Asks the robot to hold (lock-free, any thread): called on the loop's thread at a jump.</param>
    /// <param name="time">The supervisor's clock (the bus's): when the loop last ticked.</param>
    public OperatorInputs(int arms, double speedLimitMmPerS, Action hold, TimeProvider time)
    {
        _ageMs = new double[arms];
        _speedLimit = speedLimitMmPerS;
        _hold = hold;
        _time = time;
    }

    public OperatorPedal Pedal => (OperatorPedal)_pedal;

    public OperatorPedal EmergencyStop => (OperatorPedal)_emergencyStop;

    /// <summary>When the loop last ticked, on the supervisor's clock (0: never).</summary>
    public long LastTick => Volatile.Read(ref _lastTick);

    public double AgeMs(int arm) => (uint)arm < (uint)_ageMs.Length ? Volatile.Read(ref _ageMs[arm]) : 0;

    public void ReportTick() => Volatile.Write(ref _lastTick, _time.GetTimestamp());

    public void ReportAge(int arm, double ageMs)
    {
        if ((uint)arm < (uint)_ageMs.Length)
        {
            Volatile.Write(ref _ageMs[arm], double.IsNaN(ageMs) ? double.PositiveInfinity : ageMs);
        }
    }

    /// <summary>False (and the robot asked to hold) when <paramref name="mmPerS"/> is beyond what a hand can do; NaN counts as beyond.</summary>
    public bool ReportSpeed(int arm, double mmPerS)
    {
        if (mmPerS <= _speedLimit)
        {
            return true;
        }

        _hold();
        Volatile.Write(ref _jumpArm, arm);
        Volatile.Write(ref _jumpSpeed, mmPerS);
        Volatile.Write(ref _jumps, _jumps + 1);
        return false;
    }

    /// <summary>Implausible samples reported so far (the supervisor's check records a trip when it grows).</summary>
    public long Jumps => Volatile.Read(ref _jumps);

    /// <summary>The arm and speed of the latest implausible sample.</summary>
    public (int Arm, double MmPerS) LatestJump => (Volatile.Read(ref _jumpArm), Volatile.Read(ref _jumpSpeed));

    public void ReportPedal(bool down) => _pedal = (int)(down ? OperatorPedal.Down : OperatorPedal.Up);

    public void ReportEmergencyStop(bool pressed) => _emergencyStop = (int)(pressed ? OperatorPedal.Down : OperatorPedal.Up);
}

/// <summary>An operator pedal or button as the graph reports it.</summary>
public enum OperatorPedal
{
    /// <summary>Never reported: the graph has none.</summary>
    None,

    /// <summary>Released.</summary>
    Up,

    /// <summary>Pressed.</summary>
    Down,
}
