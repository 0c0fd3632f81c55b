#!/bin/sh
# Cross-build the KV11Z image (and the qemu tick benchmark), print flash/RAM use, and fail if
# any floating-point helper (soft-float __aeabi_f*/__aeabi_d*, conversions, libgcc sf/df) is linked.
# usage: firmware/build-arm.sh [build-dir]     (default: build/firmware-arm)
set -eu
FW=$(cd "$(dirname "$0")" && pwd)
OUT=${1:-$FW/../build/firmware-arm}
if ! command -v arm-none-eabi-gcc >/dev/null 2>&1; then
    echo "SKIP: arm-none-eabi-gcc not found"
    exit 0
fi
cmake -S "$FW/ports/kv11z" -B "$OUT" -DCMAKE_TOOLCHAIN_FILE="$FW/ports/kv11z/toolchain-arm-none-eabi.cmake" \
      -DCMAKE_BUILD_TYPE=MinSizeRel >/dev/null
cmake --build "$OUT" -j2 >/dev/null
ELF="$OUT/rcfw_kv11z.elf"
arm-none-eabi-size "$ELF"
arm-none-eabi-size "$ELF" | awk 'NR==2 { printf "flash (text+data) = %d bytes of 131072, RAM (data+bss incl. 2 KB stack) = %d bytes of 16384\n", $1+$2, $2+$3 }'
FLOAT=$(arm-none-eabi-nm "$ELF" "$OUT/rcfw_tickbench.elf" | grep -E '__aeabi_([fd][a-z0-9]*|[a-z0-9]*2[fd][a-z]*|c[fd][a-z]*)$|__(add|sub|mul|div|neg|float|fix|extend|trunc|cmp|eq|ne|lt|le|gt|ge|un)[a-z]*[sdt]f[0-9]?$' || true)
if [ -n "$FLOAT" ]; then
    echo "FAIL: floating point in the image:"
    echo "$FLOAT"
    exit 1
fi
echo "no floating-point symbols"
