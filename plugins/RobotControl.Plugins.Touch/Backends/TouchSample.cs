namespace RobotControl.Plugins.Touch.Backends;

/// <summary>One reading of a Geomagic Touch in its own frame (x right, y up, z toward the user).</summary>
/// <param name="XMm">Stylus tip x, mm.</param>
/// <param name="YMm">Stylus tip y, mm.</param>
/// <param name="ZMm">Stylus tip z, mm.</param>
/// <param name="RollRad">Gimbal roll, radians.</param>
/// <param name="PitchRad">Gimbal pitch, radians.</param>
/// <param name="YawRad">Gimbal yaw, radians.</param>
/// <param name="Button1">First stylus button (the clutch in the shipped graphs).</param>
/// <param name="Button2">Second stylus button.</param>
/// <param name="AgeMs">How old the reading is when the loop gets it, ms (0: read this tick; the real device counts wall time since its servo frame last changed); it grows while the device gives no new reading.</param>
public readonly record struct TouchSample(double XMm, double YMm, double ZMm, double RollRad, double PitchRad, double YawRad, bool Button1, bool Button2, double AgeMs = 0);

/// <summary>A force for the device to render, newtons, device frame.</summary>
/// <param name="XN">Force along x.</param>
/// <param name="YN">Force along y.</param>
/// <param name="ZN">Force along z.</param>
/// <param name="Enabled">False when the run level forbids force: the device renders none.</param>
public readonly record struct TouchForce(double XN, double YN, double ZN, bool Enabled = true);
