#!/bin/sh
# Count executed instructions of one 4-motor control tick under qemu (one instruction per
# translation block, exec trace), between bench_mark_begin and bench_mark_end.
# usage: count-tick.sh <arm build dir>   (after firmware/build-arm.sh)
set -eu
# qemu is needed only by this benchmark, so it is installed here rather than by tools/bootstrap.sh.
if ! command -v qemu-system-arm >/dev/null 2>&1; then
  echo "count-tick: installing qemu-system-arm"
  DEBIAN_FRONTEND=noninteractive apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends qemu-system-arm >/dev/null
fi
B=${1:-build/firmware-arm}
ELF="$B/rcfw_tickbench.elf"
BEGIN=$(arm-none-eabi-nm "$ELF" | awk '$3=="bench_mark_begin"{print $1}')
END=$(arm-none-eabi-nm "$ELF" | awk '$3=="bench_mark_end"{print $1}')
LOG=$(mktemp)
timeout 120 qemu-system-arm -M microbit -nographic -singlestep -semihosting-config enable=on,target=native \
    -kernel "$ELF" -d exec,nochain -D "$LOG"
awk -v b="$BEGIN" -v e="$END" '
  { split($4, f, "/"); pc = f[2] }
  pc == b { n = 0; on = 1; next }
  pc == e && on { c[k++] = n - 2; on = 0; next }   # minus the marker body (nop, bx lr)
  on { n++ }
  END {
    # sort
    for (i = 0; i < k; i++) for (j = i + 1; j < k; j++) if (c[j] < c[i]) { t = c[i]; c[i] = c[j]; c[j] = t }
    printf "ticks measured: %d\ninstructions per 4-motor tick: min %d, median %d, max %d\n", k, c[0], c[int(k/2)], c[k-1]
  }' "$LOG"
python3 "$(dirname "$0")/cycles.py" "$ELF" "$LOG"
rm -f "$LOG"
