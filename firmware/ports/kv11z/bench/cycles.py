#!/usr/bin/env python3
"""Estimate Cortex-M0+ cycles of the traced control ticks: executed instructions from qemu's exec
trace (one instruction per block), weighted with the Cortex-M0+ TRM timings (zero-wait memory:
ALU/MULS 1, LDR/STR 2, LDM/STM/PUSH 1+N, POP with PC 3+N, taken branch 2, BL 3, BX/BLX 2).
usage: cycles.py <tickbench.elf> <qemu exec trace>"""
import bisect, re, subprocess, sys

elf, trace = sys.argv[1:3]
dis = subprocess.run(["arm-none-eabi-objdump", "-d", elf], capture_output=True, text=True).stdout
ins = {}
for line in dis.splitlines():
    m = re.match(r"\s+([0-9a-f]+):\s+([0-9a-f]{4})(?: ([0-9a-f]{4}))?\s+(\S+)\s*(.*)", line)
    if m:
        ins[int(m.group(1), 16)] = (m.group(4), m.group(5), 4 if m.group(3) else 2)
nm = subprocess.run(["arm-none-eabi-nm", elf], capture_output=True, text=True).stdout
sym = {l.split()[2]: int(l.split()[0], 16) for l in nm.splitlines() if len(l.split()) == 3}
b, e = sym["bench_mark_begin"], sym["bench_mark_end"]

def cost(pc, nxt):
    op, args, size = ins[pc]
    op = op.split(".")[0]
    taken = nxt is not None and nxt != pc + size
    nregs = len(re.findall(r"r\d+|lr|pc", args.split("{")[-1])) if "{" in args else 0
    if op.startswith("ldm") or op.startswith("stm") or op == "push":
        return 1 + nregs
    if op == "pop":
        return (3 if "pc" in args else 1) + nregs
    if op.startswith("ldr") or op.startswith("str"):
        return 2
    if op == "bl":
        return 3
    if op in ("bx", "blx"):
        return 2
    if op.startswith("b") and op not in ("bic", "bics"):
        return 2 if taken else 1
    return 1

pcs = []
for line in open(trace):
    f = line.split()
    if len(f) > 3 and f[3].startswith("["):
        pcs.append(int(f[3].strip("[]").split("/")[1], 16))
ticks, on, cur = [], False, 0
for i, pc in enumerate(pcs):
    if pc == b:
        on, cur, n = True, 0, 0
        continue
    if pc == e and on:
        ticks.append((cur, n))
        on = False
        continue
    if on and pc in ins:
        cur += cost(pc, pcs[i + 1] if i + 1 < len(pcs) else None)
        n += 1
ticks.sort()
c = [t[0] for t in ticks]
print("ticks %d: cycles min %d median %d max %d (zero wait states)" % (len(c), c[0], c[len(c) // 2], c[-1]))
for mhz in (72, 75):
    print("  at %d MHz: median %.1f us = %.1f %% of a 100 us (10 kHz) period" % (mhz, c[len(c) // 2] / mhz, c[len(c) // 2] / mhz))
