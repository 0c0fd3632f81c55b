#!/usr/bin/env bash
# Installs what the build and tests need on a fresh machine of this kind (Debian, .NET SDK, gcc, cmake present).
# Idempotent: installs only what is missing. Run as root (CI and the dev machines run as root).
set -euo pipefail

need=()
command -v socat >/dev/null 2>&1 || need+=(socat)
command -v arm-none-eabi-gcc >/dev/null 2>&1 || need+=(gcc-arm-none-eabi libnewlib-arm-none-eabi)
command -v clang-14 >/dev/null 2>&1 || command -v clang >/dev/null 2>&1 || need+=(clang)
[ -e /usr/lib/llvm-14/lib/clang/14.0.6/lib/linux/libclang_rt.fuzzer-x86_64.a ] || need+=(libclang-rt-14-dev)
[ -e /usr/include/kdl/chain.hpp ] || need+=(liborocos-kdl-dev)
command -v cmake >/dev/null 2>&1 || need+=(cmake)
# firmware/flash.sh programs the KV11Z through OpenOCD; its test (firmware/tests/test_flash.sh) checks the target
# configuration against OpenOCD's dummy adapter.
command -v openocd >/dev/null 2>&1 || need+=(openocd)
# The analysis maps' font (src/RobotControl.Analysis/Plotting/PlotFont.cs); SkiaSharp's NoDependencies build has no
# fontconfig and finds no text font without it.
[ -e /usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf ] || need+=(fonts-dejavu-core)
# check_urdf validates the URDF that `robotctl urdf` writes (tests/RobotControl.Kinematics.Tests/Urdf).
command -v check_urdf >/dev/null 2>&1 || need+=(liburdfdom-tools)
# The web console's page tests run in Debian's headless Chromium (tests/RobotControl.Console.Tests); nothing downloads
# a browser. Node/npm build the console's front-end (src/RobotControl.Console/web: npm ci of the versions package-lock.json
# pins, run by the .NET build; docs/dependencies.md).
[ -x /usr/bin/chromium ] || need+=(chromium)
command -v npm >/dev/null 2>&1 || need+=(nodejs npm)
# Python runs the graph and trajectory generators, the firmware's mutation list, and wraps the CLI's Ctrl+C tests.
command -v python3 >/dev/null 2>&1 || need+=(python3)
# `bench realtime`'s busy scenario keeps one core busy with stress-ng (bench/RobotControl.Bench/Realtime).
command -v stress-ng >/dev/null 2>&1 || need+=(stress-ng)
# ... and measures the machine's own scheduling latency with cyclictest (rt-tests) before each scenario.
command -v cyclictest >/dev/null 2>&1 || need+=(rt-tests)
# The link plug-ins (plugins/RobotControl.Plugins.Link) talk through a NATS server; their tests start their own
# nats-server on a free loopback port (tests/RobotControl.TestSupport/Nats).
command -v nats-server >/dev/null 2>&1 || need+=(nats-server)

if [ ${#need[@]} -gt 0 ]; then
  echo "bootstrap: installing ${need[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi
