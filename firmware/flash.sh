#!/usr/bin/env bash
# Flash the KV11Z motor-module firmware through a debug probe with OpenOCD, verify it, reset the module, then read
# its firmware version back over the RS-485 bus with robotctl. Wiring, probes and what each failure means:
# docs/bring-up.md.
#
# usage: firmware/flash.sh [--probe cmsis-dap|jlink|dummy] [--image rcfw_kv11z.elf | --build-dir dir] [--no-build]
#                          [--transport serial:/dev/ttyUSB0] [--module-id id] [--speed kHz] [--openocd path]
#                          [--robotctl command] [--dry-run] [--check-config]
#   --probe        cmsis-dap (default), jlink, or dummy (OpenOCD's dummy adapter: no hardware; the target never answers)
#   --image        the ELF to program (default: built by firmware/build-arm.sh into --build-dir)
#   --build-dir    where build-arm.sh builds (default: build/firmware-arm)
#   --no-build     program the image already built, do not run build-arm.sh
#   --transport    the bus, as robotctl takes it (default: serial:/dev/ttyUSB0 at the control table's default baud)
#   --module-id    the ID expected to answer afterwards (default: any; a fresh board answers at the default ID)
#   --speed        SWD clock, kHz (default: the target configuration's)
#   --openocd      the OpenOCD program (default: openocd on PATH)
#   --robotctl     how to run robotctl (default: $ROBOTCTL, robotctl on PATH, or the built robotctl.dll)
#   --dry-run      print the commands it would run (build, openocd, read-back) and stop; needs no openocd, no probe
#   --check-config run OpenOCD against its dummy adapter to check that the target configuration loads (no probe)
# Exit codes: 0 flashed and answering; 2 bad arguments; 3 openocd missing; 4 no probe; 5 target not answering on SWD;
# 6 verify failed; 7 other OpenOCD failure; 8 module not answering on the bus; 9 wrong firmware version; 10 image missing.
set -uo pipefail

FW=$(cd "$(dirname "$0")" && pwd)
REPO=$(cd "$FW/.." && pwd)
TABLE="$FW/protocol/control-table.json"
# The OpenOCD target configuration for the MKV11Z128VLH7: Kinetis KL series, "also used for Cortex-M0+ equipped
# members of KVx" (target/klx.cfg of OpenOCD 0.12); its flash driver is kinetis.
TARGET_CFG=target/klx.cfg
CHIP=kv11z

fail() { # code, one line
    echo "flash.sh: $2" >&2
    exit "$1"
}

# A field of the control table (the firmware's single source): its default, or the baud its default code names.
table() {
    python3 - "$TABLE" "$1" <<'EOF'
import json, sys
fields = {f["name"]: f for f in json.load(open(sys.argv[1]))["fields"]}
what = sys.argv[2]
if what == "baud":
    f = fields["baud_rate"]
    print(f["codes"][str(f["default"])])
else:
    print(fields[what]["default"])
EOF
}

probe=cmsis-dap image="" build_dir="$REPO/build/firmware-arm" build=1 transport="" module_id="" speed=""
openocd=openocd robotctl="${ROBOTCTL:-}" dry_run=0 check_config=0
while [ $# -gt 0 ]; do
    case "$1" in
        --probe|--image|--build-dir|--transport|--module-id|--speed|--openocd|--robotctl)
            [ $# -ge 2 ] && [ -n "$2" ] || fail 2 "$1: needs a value (see the usage at the top of firmware/flash.sh)"
            case "$1" in
                --probe) probe=$2 ;;
                --image) image=$2 ;;
                --build-dir) build_dir=$2 ;;
                --transport) transport=$2 ;;
                --module-id) module_id=$2 ;;
                --speed) speed=$2 ;;
                --openocd) openocd=$2 ;;
                --robotctl) robotctl=$2 ;;
            esac
            shift 2 ;;
        --no-build) build=0; shift ;;
        --dry-run) dry_run=1; shift ;;
        --check-config) check_config=1; shift ;;
        -h|--help) sed -n '2,/^set -uo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) fail 2 "unknown argument '$1' (known: --probe --image --build-dir --no-build --transport --module-id --speed --openocd --robotctl --dry-run --check-config)" ;;
    esac
done

case "$probe" in
    cmsis-dap) interface=interface/cmsis-dap.cfg; select="transport select swd" ;;
    jlink) interface=interface/jlink.cfg; select="transport select swd" ;;
    dummy) interface=interface/dummy.cfg; select="transport select jtag" ;; # the dummy adapter speaks JTAG only
    *) fail 2 "--probe '$probe': not a probe this script drives (cmsis-dap, jlink, dummy)" ;;
esac
if [ -n "$speed" ] && ! [[ "$speed" =~ ^[1-9][0-9]{0,5}$ ]]; then
    fail 2 "--speed '$speed': a clock in kHz, 1..999999"
fi
if [ -n "$module_id" ]; then
    [[ "$module_id" =~ ^[0-9]{1,3}$ ]] && [ "$module_id" -le 252 ] || fail 2 "--module-id '$module_id': a bus ID, 0..252"
fi
[ -n "$transport" ] || transport="serial:/dev/ttyUSB0?baud=$(table baud)"

# The OpenOCD command: the probe, SWD, the chip, its Kinetis configuration, then program + verify + reset.
openocd_command() { # action
    local cmd=("$openocd" -f "$interface" -c "$select" -c "set CHIPNAME $CHIP" -f "$TARGET_CFG")
    [ -n "$speed" ] && cmd+=(-c "adapter speed $speed")
    cmd+=(-c "$1")
    printf '%s\n' "${cmd[@]}"
}
show() { # prints a command line, quoting words with spaces
    local out="" w
    for w in "$@"; do
        case "$w" in *[[:space:]]*) out+="'$w' " ;; *) out+="$w " ;; esac
    done
    echo "${out% }"
}

if [ "$check_config" = 1 ]; then
    command -v "$openocd" >/dev/null 2>&1 || fail 3 "openocd not found ('$openocd'): apt-get install openocd (or bash tools/bootstrap.sh)"
    mapfile -t cmd < <(probe=dummy; interface=interface/dummy.cfg; select="transport select jtag"; openocd_command shutdown)
    if out=$("${cmd[@]}" 2>&1) && grep -q "add flash_bank kinetis" <<<"$out"; then
        echo "openocd configuration loads: $(show "${cmd[@]}")"
        exit 0
    fi
    fail 7 "the OpenOCD configuration does not load ($TARGET_CFG with the kinetis flash driver): $(grep -m1 -i error <<<"$out" || echo "${out##*$'\n'}")"
fi

# The image: given, or built here (build-arm.sh skips without arm-none-eabi-gcc: then it is missing).
if [ -z "$image" ]; then
    image="$build_dir/rcfw_kv11z.elf"
    if [ "$build" = 1 ]; then
        if [ "$dry_run" = 1 ]; then
            echo "build: $(show "$FW/build-arm.sh" "$build_dir")"
        else
            "$FW/build-arm.sh" "$build_dir" >/dev/null || fail 10 "building the image failed: run firmware/build-arm.sh $build_dir to see why"
        fi
    fi
fi
if [ "$dry_run" = 0 ] || [ "$build" = 0 ] || [ "$image" != "$build_dir/rcfw_kv11z.elf" ]; then
    [ -f "$image" ] || fail 10 "image $image missing: build it with firmware/build-arm.sh (needs gcc-arm-none-eabi) or give --image"
fi

version=$(table firmware_version)
mapfile -t cmd < <(openocd_command "program $image verify reset exit")
readback=(discover "$transport")
if [ "$dry_run" = 1 ]; then
    echo "openocd: $(show "${cmd[@]}")"
    echo "read back: $(show robotctl "${readback[@]}") (expects firmware $version${module_id:+ at id $module_id})"
    exit 0
fi

command -v "$openocd" >/dev/null 2>&1 || fail 3 "openocd not found ('$openocd'): apt-get install openocd (or bash tools/bootstrap.sh)"
log=$(mktemp "${TMPDIR:-/tmp}/flash-openocd.XXXXXX.log")
echo "flashing $image with $probe: $(show "${cmd[@]}")"
if ! "${cmd[@]}" >"$log" 2>&1 || grep -qiE "verify failed|programming failed" "$log"; then
    if grep -qiE "unable to find a matching CMSIS-DAP device|No J-Link device found|no device found|unable to open (CMSIS-DAP|J-Link)" "$log"; then
        fail 4 "no $probe probe found: plug it in (lsusb should list it) and check its USB permissions; OpenOCD's log: $log"
    elif grep -qiE "verify failed" "$log"; then
        fail 6 "verify failed: the flash does not read back as $image (flash security, a failing flash, a power dip); OpenOCD's log: $log"
    elif grep -qiE "is secured|secured MCU" "$log"; then
        fail 5 "the KV11Z is secured: it must be mass-erased first (kinetis mdm mass_erase); OpenOCD's log: $log"
    elif grep -qiE "Invalid ACK|Error connecting DP|IR capture error|JTAG scan chain|debug port|Failed to read memory|examination failed|target not examined" "$log"; then
        fail 5 "the $probe probe is there but no KV11Z answers on its debug port (SWD): check the SWD header wiring, the module's power and its reset line; OpenOCD's log: $log"
    fi
    fail 7 "openocd failed: $(grep -m1 -E '^Error' "$log" || tail -n1 "$log"); OpenOCD's log: $log"
fi

# The module restarts from reset; a fresh one answers at the default ID and baud.
if [ -z "$robotctl" ]; then
    if command -v robotctl >/dev/null 2>&1; then
        robotctl=robotctl
    elif [ -f "$REPO/src/RobotControl.Cli/bin/Release/net10.0/robotctl.dll" ]; then
        robotctl="dotnet $REPO/src/RobotControl.Cli/bin/Release/net10.0/robotctl.dll"
    else
        robotctl="dotnet run --project $REPO/src/RobotControl.Cli -c Release --"
    fi
fi
sleep 1
# shellcheck disable=SC2086 # the robotctl command may be several words
found=$($robotctl "${readback[@]}" 2>&1) || true
answers=$(awk '/^id +[0-9]+ +model [0-9]+ +firmware [0-9]+/ { print $2, $6 }' <<<"$found")
if [ -n "$module_id" ]; then
    answers=$(awk -v id="$module_id" '$1 == id' <<<"$answers")
fi
if [ -z "$answers" ]; then
    fail 8 "no module${module_id:+ $module_id} answered on $transport after flashing: check the RS-485 wiring (A/B), the module's power and the baud (a fresh module runs at $(table baud)); robotctl said: $(tail -n1 <<<"$found")"
fi
while read -r id fw; do
    [ "$fw" = "$version" ] || fail 9 "module $id reports firmware $fw, the image is version $version: did the reset run the new image?"
    echo "flashed $image (firmware $version) with $probe; module $id answers with firmware $fw on $transport"
done <<<"$answers"
exit 0
