#!/usr/bin/env bash
# Mutation testing of the safety-relevant code. Not part of the README's test command: a full run takes tens of
# minutes. Reports go to out/mutation/; record the scores in docs/testing.md with the date and this command.
#
#   bash tools/mutation.sh                 # every .NET target below, then the firmware list
#   bash tools/mutation.sh dotnet [NAME…]  # Stryker.NET only (NAME: Kinematics, Bus, Robot, Robot.Core, ...)
#   bash tools/mutation.sh firmware        # the firmware's hand-written mutations only
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
out="$root/out/mutation"
mkdir -p "$out"

# target : its test project (the mirrored one). A target is a production project, or a part of one: then its
# tools/mutation/<target>.json names the project ("project") and the part ("mutate").
targets=(
  "Definitions:tests/RobotControl.Definitions.Tests"
  "Kinematics:tests/RobotControl.Kinematics.Tests"
  "Bus:tests/RobotControl.Bus.Tests"
  "Robot:tests/RobotControl.Robot.Tests"
  "Robot.Core:tests/RobotControl.Robot.Tests"
  "Runtime:tests/RobotControl.Runtime.Tests"
  "Host:tests/RobotControl.Host.Tests"
  "Plugins.Standard:tests/RobotControl.Plugins.Standard.Tests"
  "Plugins.Touch:tests/RobotControl.Plugins.Touch.Tests"
)

what="${1:-all}"
shift || true

# The machine's cores are shared: Stryker runs at the lowest priority, two test sessions at a time by default.
concurrency="${MUTATION_CONCURRENCY:-2}"
status=0

run_dotnet() {
  dotnet tool restore >/dev/null
  for t in "${targets[@]}"; do
    name="${t%%:*}"
    tests="${t#*:}"
    if [ $# -gt 0 ] && [[ " $* " != *" $name "* ]]; then
      continue
    fi
    # The production project: the config's "project" (RobotControl.X.csproj), else RobotControl.<target>.
    pname="$name"
    if [ -f "$root/tools/mutation/$name.json" ]; then
      pname="$(python3 -c 'import json, sys; p = json.load(open(sys.argv[1]))["stryker-config"].get("project", ""); print(p.removeprefix("RobotControl.").removesuffix(".csproj"))' "$root/tools/mutation/$name.json")"
      [ -n "$pname" ] || pname="$name"
    fi
    project="src/RobotControl.$pname/RobotControl.$pname.csproj"
    [ -f "$project" ] || project="plugins/RobotControl.$pname/RobotControl.$pname.csproj"
    if [ ! -f "$project" ] || [ ! -d "$tests" ]; then
      echo "mutation: $name: no $project or no $tests; skipped"
      continue
    fi
    # The scope (which files are mutated, and why) is in tools/mutation/<Project>.json; without one, the whole project.
    config=("--project" "RobotControl.$pname.csproj" "--configuration" "Release")
    [ -f "$root/tools/mutation/$name.json" ] && config=("--config-file" "$root/tools/mutation/$name.json")
    echo "== Stryker.NET: $name (RobotControl.$pname; tests: $tests, concurrency $concurrency)"
    rm -rf "$out/$name"
    (cd "$tests" && nice -n 19 dotnet stryker "${config[@]}" --concurrency "$concurrency" \
      --reporter json --reporter html --reporter progress --output "$out/$name" >"$out/$name.log" 2>&1) || {
      echo "mutation: $name: Stryker failed; see $out/$name.log"; status=1; continue; }
    python3 - "$out/$name/reports/mutation-report.json" "$name" <<'PY'
import json, sys
report = json.load(open(sys.argv[1]))
counts = {}
for f in report["files"].values():
    for m in f["mutants"]:
        counts[m["status"]] = counts.get(m["status"], 0) + 1
detected = counts.get("Killed", 0) + counts.get("Timeout", 0)
valid = detected + counts.get("Survived", 0) + counts.get("NoCoverage", 0)
score = 100.0 * detected / valid if valid else 0.0
print(f"{sys.argv[2]}: score {score:.1f} % ({detected} detected of {valid}; " +
      ", ".join(f"{k} {v}" for k, v in sorted(counts.items())) + ")")
PY
  done
}

case "$what" in
  dotnet) run_dotnet "$@" ;;
  firmware) python3 firmware/tools/mutate.py --json "$out/firmware.json" ;;
  all) run_dotnet; python3 firmware/tools/mutate.py --json "$out/firmware.json" ;;
  *) echo "usage: bash tools/mutation.sh [all|dotnet [NAME...]|firmware]"; exit 2 ;;
esac
exit "$status"
