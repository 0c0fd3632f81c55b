#!/usr/bin/env python3
"""Mutation testing of the firmware core: applies each hand-written mutation in
firmware/tests/mutation/mutations.json, one at a time, to a copy of firmware/, rebuilds, runs CTest, and reports the
mutations no test kills (survivors). Exit status 0 only when every mutation applies and is killed.

    python3 firmware/tools/mutate.py [--only ID[,ID...]] [--json report.json] [--keep]
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
FIRMWARE = os.path.dirname(HERE)
LIST = os.path.join(FIRMWARE, "tests", "mutation", "mutations.json")
# The Cortex-M0+ image check builds a cross image and says nothing about behaviour, and flash_script tests a shell
# script that runs no firmware C: neither is run per mutant.
CTEST_EXCLUDE = "arm_build_size_nofloat|flash_script"


def run(cmd, cwd, timeout):
    try:
        p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout, text=True)
        return p.returncode, p.stdout
    except subprocess.TimeoutExpired as e:
        return 124, (e.stdout or "") if isinstance(e.stdout, str) else ""


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--only", help="comma-separated mutation ids")
    ap.add_argument("--json", help="write the results here")
    ap.add_argument("--keep", action="store_true", help="keep the scratch copy")
    args = ap.parse_args()

    with open(LIST, encoding="utf-8") as f:
        mutations = json.load(f)["mutations"]
    if args.only:
        wanted = set(args.only.split(","))
        unknown = wanted - {m["id"] for m in mutations}
        if unknown:
            print(f"mutate.py: --only: no mutation with id {', '.join(sorted(unknown))} in {LIST}")
            return 2
        mutations = [m for m in mutations if m["id"] in wanted]
    ids = [m["id"] for m in mutations]
    if len(ids) != len(set(ids)):
        print(f"mutate.py: {LIST}: duplicate mutation ids")
        return 2

    scratch = tempfile.mkdtemp(prefix="rcfw-mutate-")
    src = os.path.join(scratch, "firmware")
    build = os.path.join(scratch, "build")
    shutil.copytree(FIRMWARE, src, ignore=shutil.ignore_patterns("build", "build-*", "__pycache__"))
    started = time.monotonic()
    code, out = run(["cmake", "-S", src, "-B", build, "-DCMAKE_BUILD_TYPE=Release"], scratch, 300)
    if code == 0:
        code, out = run(["cmake", "--build", build, "-j2"], scratch, 600)
    if code == 0:
        code, out = run(["ctest", "--test-dir", build, "-E", CTEST_EXCLUDE, "--timeout", "120"], scratch, 900)
    if code != 0:
        print("mutate.py: the unmutated firmware does not build or pass its tests; fix that first")
        print(out[-3000:])
        return 2

    results = []
    for m in mutations:
        path = os.path.join(src, m["file"])
        with open(path, encoding="utf-8") as f:
            original = f.read()
        count = original.count(m["find"])
        if count != 1:
            outcome, detail = "does-not-apply", f"'find' occurs {count} times in {m['file']}"
        else:
            with open(path, "w", encoding="utf-8") as f:
                f.write(original.replace(m["find"], m["replace"]))
            code, out = run(["cmake", "--build", build, "-j2"], scratch, 600)
            if code != 0:
                outcome, detail = "killed-by-compiler", out.strip().splitlines()[-1] if out.strip() else ""
            else:
                code, out = run(["ctest", "--test-dir", build, "-E", CTEST_EXCLUDE, "--timeout", "60"], scratch, 900)
                if code == 0:
                    outcome, detail = "SURVIVED", "every CTest test passed"
                else:
                    outcome = "killed"
                    detail = "; ".join(line.strip() for line in out.splitlines() if "Failed" in line or "Timeout" in line or "Exception" in line or "SEGFAULT" in line)[:300]
            with open(path, "w", encoding="utf-8") as f:
                f.write(original)
        results.append({"id": m["id"], "file": m["file"], "why": m["why"], "outcome": outcome, "detail": detail})
        print(f"{outcome:18} {m['id']:40} {m['why']}", flush=True)

    # Rebuild the unmutated tree so --keep leaves a usable copy.
    run(["cmake", "--build", build, "-j2"], scratch, 600)
    survivors = [r for r in results if r["outcome"] in ("SURVIVED", "does-not-apply")]
    killed = sum(1 for r in results if r["outcome"].startswith("killed"))
    elapsed = time.monotonic() - started
    print(f"{killed} killed, {len(survivors)} survived or did not apply, of {len(results)} mutations ({elapsed:.0f} s)")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump({"killed": killed, "survived": len(survivors), "total": len(results), "seconds": round(elapsed), "results": results}, f, indent=1)
    if not args.keep:
        shutil.rmtree(scratch, ignore_errors=True)
    else:
        print(f"scratch copy kept in {scratch}")
    return 0 if not survivors else 1


if __name__ == "__main__":
    sys.exit(main())
