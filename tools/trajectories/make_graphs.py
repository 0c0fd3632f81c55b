#!/usr/bin/env python3
"""Writes graphs/teleop-lb.json, graphs/teleop-crb.json and graphs/teleop-lb-coppeliasim.json: two simulated Touch devices replay the demonstration
trajectories through homing (left arm mirrored), scaling, clutch and IK into the robot; the IK's workspace force goes
back through the haptic walls (which take the scaling's ratio in effect) and damping to the device one tick later. The homing origin is the tool position of
the IK's start pose (forward kinematics below, the same DH convention as the robot files). The CoppeliaSim variant
also wires the IK's joint outputs into one CoppeliaSim bridge instance, `sim`, which drives the imported model."""
import json, math, os

ROBOTS = {
    "lb": dict(file="../hardware/robots/lb-1.0.json",
               joints=["shoulder_yaw", "shoulder_pitch", "shoulder_roll", "elbow", "tool_roll"],
               dh=[(0, 0, 0, 0, None), (90, 0, 0, 0, 0), (90, 0, 0, 90, 1), (90, 0, 87.57, 90, 2), (90, 0, 0, 180, 3), (90, 0, 86.59, 180, 4)],
               home=[-30, -30, 0, 90, 0]),
    "crb": dict(file="../hardware/robots/crb-1.0.json",
                joints=["shoulder_yaw", "shoulder_pitch", "elbow", "tool_roll"],
                dh=[(0, 0, 0, 0, None), (90, 0, 0, 0, 0), (-90, 68.58, 0, 0, 1), (90, 0, 0, 90, 2), (0, 0, 96.393, 0, 3)],
                home=[-30, -30, 60, 0]),
}

def fk(dh, q):
    d2r = math.pi / 180
    T = [[1 if i == j else 0 for j in range(4)] for i in range(4)]
    for al, a, d, th, j in dh:
        t = (th + (q[j] if j is not None else 0)) * d2r
        ct, st, ca, sa = math.cos(t), math.sin(t), math.cos(al * d2r), math.sin(al * d2r)
        A = [[ct, -st * ca, st * sa, a * ct], [st, ct * ca, -ct * sa, a * st], [0, sa, ca, d], [0, 0, 0, 1]]
        T = [[sum(T[i][k] * A[k][j] for k in range(4)) for j in range(4)] for i in range(4)]
    return [T[0][3], T[1][3], T[2][3]]

def graph(name, r):
    ox, oy, oz = (round(v, 4) for v in fk(r["dh"], r["home"]))
    ratio, roll = 0.5, 90
    instances, wires = [], []
    for side in ("right", "left"):
        mirror = side == "left"
        instances += [
            {"name": f"touch_{side}", "type": "touch", "settings": {"script": f"trajectories/demo-{side}.csv"}},
            {"name": f"homing_{side}", "type": "homing", "settings": {"origin_x_mm": ox, "origin_y_mm": oy, "origin_z_mm": oz, "roll_deg": roll, "mirror": mirror}},
            {"name": f"scaling_{side}", "type": "scaling", "settings": {"ratio": ratio, "reference_x_mm": ox, "reference_y_mm": oy, "reference_z_mm": oz}},
            {"name": f"clutch_{side}", "type": "clutch", "settings": {}},
            {"name": f"ik_{side}", "type": "inverse_kinematics", "settings": {"initial_joints_deg": ",".join(str(v) for v in r["home"])}},
            {"name": f"walls_{side}", "type": "haptic_walls", "settings": {"roll_deg": roll, "mirror": mirror}},
            {"name": f"damping_{side}", "type": "viscous_damping", "settings": {}},
        ]
        w = lambda a, b, delayed=False: wires.append({"from": a, "to": b, **({"delayed": True} if delayed else {})})
        for c in ("x", "y", "z", "roll", "pitch", "yaw"):
            w(f"touch_{side}.{c}", f"homing_{side}.{c}")
        for c in ("x", "y", "z"):
            w(f"homing_{side}.{c}", f"scaling_{side}.{c}")
            w(f"scaling_{side}.{c}", f"clutch_{side}.{c}")
        for c in ("roll", "pitch", "yaw"):
            w(f"homing_{side}.{c}", f"clutch_{side}.{c}")
        w(f"touch_{side}.button1", f"clutch_{side}.clutch")
        for c in ("x", "y", "z", "roll", "pitch", "yaw"):
            w(f"clutch_{side}.{c}", f"ik_{side}.{c}")
        for j in r["joints"]:
            w(f"ik_{side}.{j}", f"robot.{side}.{j}")
        for c in ("x", "y", "z"):
            w(f"ik_{side}.f{c}", f"walls_{side}.f{c}")
            w(f"walls_{side}.f{c}", f"damping_{side}.f{c}_in")
            w(f"touch_{side}.{c}", f"damping_{side}.{c}")
            w(f"damping_{side}.f{c}", f"touch_{side}.force_{c}", True)
        # The walls undo the ratio in effect (the console changes it while the clutch is held): one source, the scaling.
        w(f"scaling_{side}.ratio", f"walls_{side}.scale_ratio")
    # The devices push only while the robot follows them; the robot node times out a device whose samples stop coming.
    for side in ("right", "left"):
        w("robot.teleop_enabled", f"touch_{side}.force_enable", True)
    for side in ("right", "left"):
        w(f"touch_{side}.sample_age_ms", f"robot.{side}.input_age_ms")
    doc = {"schema": "robotcontrol/graph/1", "robot": r["file"], "transport": "virtual", "loop_rate_hz": 1000,
           "instances": instances, "wires": wires}
    return doc

def coppeliasim_graph(name, r):
    doc = graph(name, r)
    doc["instances"].append({"name": "sim", "type": "coppeliasim", "settings": {
        "endpoint": "tcp://127.0.0.1:23000", "model": "/LB1", "mode": "kinematic", "stepping": False, "ticks_per_step": 50}})
    for side in ("right", "left"):
        for j in r["joints"]:
            doc["wires"].append({"from": f"ik_{side}.{j}", "to": f"sim.{side}.{j}"})
    return doc

if __name__ == "__main__":
    out = os.path.join(os.path.dirname(__file__), "..", "..", "graphs")
    for name, r in ROBOTS.items():
        with open(os.path.join(out, f"teleop-{name}.json"), "w") as f:
            json.dump(graph(name, r), f, indent=2)
            f.write("\n")
    with open(os.path.join(out, "teleop-lb-coppeliasim.json"), "w") as f:
        json.dump(coppeliasim_graph("lb", ROBOTS["lb"]), f, indent=2)
        f.write("\n")
