#!/usr/bin/env bash
# The main job: the headless teleoperation harness. Two simulated Geomagic Touch devices drive both LB-1.0 arms
# through homing, scaling, clutch and inverse kinematics into the virtual robot, which runs the real module
# firmware (built from firmware/ by the build). Writes report.json.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
bash tools/bootstrap.sh
dotnet run -c Release --project src/RobotControl.Cli -- run graphs/teleop-lb.json --virtual --duration 20s --report report.json "$@"
