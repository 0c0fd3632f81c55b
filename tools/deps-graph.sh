#!/usr/bin/env bash
# Regenerates the project dependency graph in docs/architecture.md from the .csproj files under src/ and plugins/
# (the test that checks it rewrites the block when ROBOTCONTROL_WRITE_DEPS_GRAPH=1). Run after changing a
# ProjectReference; commit the doc with the change.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
ROBOTCONTROL_WRITE_DEPS_GRAPH=1 dotnet test "$root/tests/RobotControl.Repository.Tests" -c Release --nologo \
  --filter "FullyQualifiedName~ArchitectureDocTests" >/dev/null
echo "docs/architecture.md: dependency graph up to date"
