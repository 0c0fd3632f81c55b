#!/usr/bin/env bash
# Runs every test: the firmware's CTest suite (host build, fuzz-corpus replay, Cortex-M0+ image checks) and the
# .NET test projects. Ends with one line "N passed, N failed" summed over both.
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
bash tools/bootstrap.sh || { echo "bootstrap failed"; exit 1; }

log="$(mktemp)"
status=0

echo "== firmware (CTest)"
if cmake -S firmware -B build/firmware -DCMAKE_BUILD_TYPE=Release >/dev/null && cmake --build build/firmware -j2 >/dev/null; then
  ctest --test-dir build/firmware --output-on-failure 2>&1 | tee -a "$log"
  [ "${PIPESTATUS[0]}" = 0 ] || status=1
else
  echo "firmware build failed"; status=1
fi

echo "== .NET (xunit)"
# Summaries, and for a failed test its message (up to its stack trace), so that a CI log says why.
dotnet test RobotControl.sln -c Release --nologo 2>&1 | tee -a "$log" \
  | awk '/^(Passed|Failed)!|error|\[FAIL\]/ { print; next } /^  Failed [A-Za-z]/ { print; show = 1; next } /Stack Trace:/ { show = 0 } show { print }' || true
[ "${PIPESTATUS[0]}" = 0 ] || status=1

read -r cf ct < <(sed -nE 's/.* ([0-9]+) tests failed out of ([0-9]+).*/\1 \2/p' "$log" | awk '{f+=$1; t+=$2} END {print f+0, t+0}')
read -r dp df < <(grep -E "^(Passed|Failed)! " "$log" | sed -nE 's/.*Failed: *([0-9]+), Passed: *([0-9]+).*/\2 \1/p' | awk '{p+=$1; f+=$2} END {print p+0, f+0}')
passed=$((ct - cf + dp)); failed=$((cf + df))
rm -f "$log"
[ "$failed" -eq 0 ] || status=1
echo "$passed passed, $failed failed"
exit $status
