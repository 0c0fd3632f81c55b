#!/usr/bin/env python3
"""Writes the demonstration hand trajectories replayed by graphs/teleop-*.json (graphs/trajectories/demo-*.csv).

Device frame of a Geomagic Touch (x right, y up, z toward the user), mm and rad, 100 keyframes/s. The script:
rest; a circle (device 120 mm/s, 60 mm/s at the robot through scaling 0.5); a clutch press while the hand
repositions; a figure-eight (peaks ~140 mm/s at the device, ~70 mm/s at the robot); another clutch press; fast
point-to-point reaches with minimum-jerk profiles; rest. Button 1 is the clutch. Deterministic: run it again to get
the same files.
"""
import math, sys, os

def smooth(u):  # 0..1 minimum-jerk blend
    u = min(1.0, max(0.0, u))
    return u * u * u * (10 - 15 * u + 6 * u * u)

def envelope(tau, length, ramp=1.0):
    return smooth(tau / ramp) * smooth((length - tau) / ramp)

def hand(t, side):
    s = 1.0 if side == "right" else -1.0  # the left hand mirrors the right hand's lateral motion
    k = 1.0 if side == "right" else 0.85  # and moves a little differently
    x = y = z = 0.0
    b1 = 0
    if 1.0 <= t < 6.0:  # circle in the horizontal plane
        tau = t - 1.0
        w = 2 * math.pi * 0.8 * k
        e = envelope(tau, 5.0)
        x = s * e * 24 * math.sin(w * tau)
        z = e * 24 * (math.cos(w * tau) - 1)
    elif 6.0 <= t < 7.5:  # clutch held from 6.2 s to 7.3 s while the hand moves up 20 mm
        y = 20 * smooth((t - 6.25) / 0.9)
        b1 = 1 if 6.2 <= t < 7.3 else 0
    elif 7.5 <= t < 13.0:  # figure-eight in the frontal plane
        tau = t - 7.5
        w = 2 * math.pi * 0.6 * k
        e = envelope(tau, 5.5)
        x = s * e * 26 * math.sin(w * tau)
        y = 20 + e * 13 * math.sin(2 * w * tau)
    elif 13.0 <= t < 14.2:  # clutch held from 13.1 s to 14.0 s while the hand moves back down
        y = 20 - 20 * smooth((t - 13.15) / 0.8)
        b1 = 1 if 13.1 <= t < 14.0 else 0
    elif 14.2 <= t < 19.0:  # reaches
        points = [(0, 0, 0), (22, 0, -12), (-18, 10, 6), (12, -10, -20), (0, 0, 0)]
        times = [14.2, 15.3, 16.0, 17.2, 18.6]
        for i in range(len(times) - 1):
            if times[i] <= t < times[i + 1] or i == len(times) - 2:
                u = smooth((t - times[i]) / (times[i + 1] - times[i]))
                a, b = points[i], points[i + 1]
                x = s * (a[0] + u * (b[0] - a[0]))
                y = a[1] + u * (b[1] - a[1])
                z = a[2] + u * (b[2] - a[2])
                break
    roll = 0.25 * math.sin(2 * math.pi * 0.2 * t) * smooth(t - 0.5)
    pitch = 0.1 * math.sin(2 * math.pi * 0.13 * t) * smooth(t - 0.5)
    yaw = 0.0
    return x, y, z, roll, pitch, yaw, b1

def main(out_dir):
    for side in ("right", "left"):
        path = os.path.join(out_dir, f"demo-{side}.csv")
        with open(path, "w") as f:
            f.write(f"# demonstration hand trajectory, {side} hand, device frame (x right, y up, z toward the user);"
                    " written by tools/trajectories/make_demo.py\n")
            f.write("time_s,x_mm,y_mm,z_mm,roll_rad,pitch_rad,yaw_rad,button1,button2\n")
            for i in range(0, 2001):
                t = i / 100.0
                x, y, z, r, p, w, b1 = hand(t, side)
                f.write(f"{t:.2f},{x:.4f},{y:.4f},{z:.4f},{r:.5f},{p:.5f},{w:.5f},{b1},0\n")

if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..", "graphs", "trajectories"))
