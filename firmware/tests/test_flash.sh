#!/usr/bin/env bash
# firmware/flash.sh without a probe: its arguments, the OpenOCD command line of --dry-run (which needs no openocd),
# and one error line per failure, from stand-in openocd and robotctl programs that print what the real ones print in
# that case; with OpenOCD (tools/bootstrap.sh installs it), also the configuration against OpenOCD's dummy adapter and the real OpenOCD's
# failure when no target answers.
set -uo pipefail
FLASH=$(cd "$(dirname "$0")/.." && pwd)/flash.sh
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
failures=0 checks=0
VERSION=$(python3 -c 'import json,sys; print(next(f["default"] for f in json.load(open(sys.argv[1]))["fields"] if f["name"] == "firmware_version"))' "$(dirname "$FLASH")/protocol/control-table.json")

# run <expected exit> <expected text> args...: the exit code, and the text in its output (stderr: exactly one line).
run() {
    local code=$1 text=$2
    shift 2
    checks=$((checks + 1))
    "$FLASH" "$@" >"$TMP/out" 2>"$TMP/err"
    local got=$?
    local lines
    lines=$(wc -l <"$TMP/err")
    if [ "$got" != "$code" ] || ! grep -qF -- "$text" "$TMP/out" "$TMP/err" || { [ "$code" != 0 ] && [ "$lines" != 1 ]; }; then
        failures=$((failures + 1))
        echo "FAIL: flash.sh $* -> exit $got (want $code), want '$text'; stdout:"; cat "$TMP/out"; echo "stderr:"; cat "$TMP/err"
    fi
}

# stand-ins: an openocd that prints $OPENOCD_SAYS and exits $OPENOCD_EXIT; a robotctl that prints $ROBOTCTL_SAYS
cat >"$TMP/openocd" <<'SH'
#!/bin/sh
printf '%b\n' "$OPENOCD_SAYS"
exit "$OPENOCD_EXIT"
SH
cat >"$TMP/robotctl" <<'SH'
#!/bin/sh
echo "robotctl $*" >"$(dirname "$0")/robotctl.args"
printf '%b\n' "$ROBOTCTL_SAYS"
SH
chmod +x "$TMP/openocd" "$TMP/robotctl"
touch "$TMP/image.elf"
fake=(--image "$TMP/image.elf" --openocd "$TMP/openocd" --robotctl "$TMP/robotctl")

# --dry-run: the command lines, with no openocd anywhere
run 0 "openocd: openocd -f interface/cmsis-dap.cfg -c 'transport select swd' -c 'set CHIPNAME kv11z' -f target/klx.cfg -c 'program $TMP/image.elf verify reset exit'" --dry-run --image "$TMP/image.elf"
run 0 "openocd: /nowhere/openocd -f interface/jlink.cfg -c 'transport select swd' -c 'set CHIPNAME kv11z' -f target/klx.cfg -c 'adapter speed 4000' -c 'program $TMP/image.elf verify reset exit'" --dry-run --image "$TMP/image.elf" --probe jlink --speed 4000 --openocd /nowhere/openocd
run 0 "read back: robotctl discover serial:/dev/ttyUSB0?baud=1000000 (expects firmware $VERSION)" --dry-run --image "$TMP/image.elf"
run 0 "build: $(dirname "$FLASH")/build-arm.sh $TMP/arm" --dry-run --build-dir "$TMP/arm"

# arguments
run 2 "flash.sh: unknown argument '--frobnicate'" --frobnicate
run 2 "flash.sh: --probe 'stlink': not a probe this script drives (cmsis-dap, jlink, dummy)" --probe stlink --dry-run
run 2 "flash.sh: --speed 'fast': a clock in kHz" --speed fast --dry-run
run 2 "flash.sh: --module-id '300': a bus ID, 0..252" --module-id 300 --dry-run
run 2 "flash.sh: --image: needs a value" --image
run 10 "flash.sh: image $TMP/none.elf missing" --image "$TMP/none.elf" --dry-run
run 10 "flash.sh: image $TMP/arm/rcfw_kv11z.elf missing" --no-build --build-dir "$TMP/arm" --dry-run

# failures, one line each
run 3 "flash.sh: openocd not found ('$TMP/no-openocd')" --image "$TMP/image.elf" --openocd "$TMP/no-openocd"
OPENOCD_EXIT=1 OPENOCD_SAYS="Error: unable to find a matching CMSIS-DAP device\n** OpenOCD init failed **" run 4 "flash.sh: no cmsis-dap probe found" "${fake[@]}"
OPENOCD_EXIT=1 OPENOCD_SAYS="Error: No J-Link device found" run 4 "flash.sh: no jlink probe found" "${fake[@]}" --probe jlink
OPENOCD_EXIT=1 OPENOCD_SAYS="Error: Error connecting DP: cannot read IDR" run 5 "no KV11Z answers on its debug port (SWD)" "${fake[@]}"
OPENOCD_EXIT=1 OPENOCD_SAYS="** Programming Started **\n** Programming Finished **\n** Verify Started **\nError: checksum mismatch - attempting binary compare\n** Verify Failed **" run 6 "flash.sh: verify failed" "${fake[@]}"
OPENOCD_EXIT=1 OPENOCD_SAYS="Error: something else entirely" run 7 "flash.sh: openocd failed: Error: something else entirely" "${fake[@]}"
ok="** Programming Finished **\n** Verified OK **\n** Resetting Target **"
OPENOCD_EXIT=0 OPENOCD_SAYS="$ok" ROBOTCTL_SAYS="0 module(s) answered on serial:/dev/ttyUSB0" run 8 "flash.sh: no module answered on serial:/dev/ttyUSB0?baud=1000000 after flashing" "${fake[@]}"
OPENOCD_EXIT=0 OPENOCD_SAYS="$ok" ROBOTCTL_SAYS="id   1  model 19761  firmware $VERSION\n1 module(s) answered" run 8 "flash.sh: no module 5 answered" "${fake[@]}" --module-id 5
OPENOCD_EXIT=0 OPENOCD_SAYS="$ok" ROBOTCTL_SAYS="id   1  model 19761  firmware 1\n1 module(s) answered" run 9 "flash.sh: module 1 reports firmware 1, the image is version $VERSION" "${fake[@]}"
OPENOCD_EXIT=0 OPENOCD_SAYS="$ok" ROBOTCTL_SAYS="id   1  model 19761  firmware $VERSION\n1 module(s) answered" run 0 "module 1 answers with firmware $VERSION on serial:/dev/ttyS4" "${fake[@]}" --transport serial:/dev/ttyS4
checks=$((checks + 1))
grep -qxF "robotctl discover serial:/dev/ttyS4" "$TMP/robotctl.args" || { failures=$((failures + 1)); echo "FAIL: read back ran: $(cat "$TMP/robotctl.args")"; }

# the real OpenOCD: the configuration loads (dummy adapter), and with no target the failure is named
if command -v openocd >/dev/null 2>&1; then
    run 0 "openocd configuration loads" --check-config
    run 5 "flash.sh: the dummy probe is there but no KV11Z answers" --probe dummy --image "$TMP/image.elf" --robotctl "$TMP/robotctl"
else
    failures=$((failures + 1))
    echo "FAIL: openocd not installed (bash tools/bootstrap.sh installs it): the dummy-adapter checks cannot run"
fi

echo "$checks checks, $failures failures"
[ "$failures" = 0 ]
