#!/usr/bin/env python3
"""make convergence (scripts/convergence.py), ctest label `convergence`: it runs here and in the
student release.

Usage: convergence_test.py --build BUILD --source KIT

Checks, each printing PASS/FAIL (the script exits non-zero if any failed):
1. A tiny study (the four labs of labs/ as they are, at 2 and 4 spp, 64x64 against the grader's
   references): exit 0, the plot named at the end; convergence.csv has a row per lab and spp,
   labs 1-3 against the depth-limited reference and lab 4 against the unbiased one, every
   figure finite and positive and seconds_256 the seconds scaled to 256x256; convergence.png is a
   PNG of the plot's size; handout.csv holds the handout's curves of the four labs.
2. Bad input (spp that are not whole numbers from 1 to 65536) is one line naming it and exit
   status 2, from the script and from `make convergence`, and writes nothing.
"""
import argparse
import csv
import math
import os
import struct
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import check, exit_code  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--build", required=True)
parser.add_argument("--source", required=True)
args = parser.parse_args()
SCRIPT = os.path.join(args.source, "scripts", "convergence.py")
sys.path.insert(0, os.path.dirname(SCRIPT))
import convergence as convergence_script  # noqa: E402

LABS = ["branching", "uniform", "importance", "roulette"]
FIGURES = ["seconds", "seconds_256", "samples_per_second", "relative_rmse", "rel_mse", "noise"]


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    if len(head) < 24 or head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        return None
    return struct.unpack(">II", head[16:24])


def run(arguments, cwd=None):
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    return subprocess.run(arguments, capture_output=True, text=True, cwd=cwd, env=env)


def check_study(scratch):
    out = os.path.join(scratch, "convergence")
    result = run([sys.executable, SCRIPT, "--build", args.build, "--spp", "4 2", "--out", out])
    check(result.returncode == 0, "a study at 2 and 4 spp: exit 0" +
          ("" if result.returncode == 0 else f": {result.stdout[-600:]}{result.stderr[-600:]}"))
    if result.returncode != 0:
        return
    last = result.stdout.splitlines()[-1]
    check(f"the plot is {os.path.abspath(out)}/convergence.png" in last,
          f"the last line names the plot: {last!r}")
    with open(os.path.join(out, "convergence.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    check([(r["lab"], int(r["spp"])) for r in rows] == [(lab, spp) for lab in LABS
                                                         for spp in (2, 4)],
          f"convergence.csv has a row per lab and spp, in order: "
          f"{[(r['lab'], r['spp']) for r in rows]}")
    check(all(r["reference"] == ("unbiased" if r["lab"] == "roulette" else "depth_limited")
              for r in rows), "labs 1-3 against the depth-limited reference, lab 4 the unbiased")
    bad = [(r["lab"], r["spp"], k, r.get(k)) for r in rows for k in FIGURES
           if not (r.get(k) and math.isfinite(float(r[k])) and float(r[k]) > 0)]
    check(not bad, f"every figure finite and positive {bad[:3] if bad else ''}")
    scaled = [float(r["seconds_256"]) / float(r["seconds"]) for r in rows]
    check(all(abs(s - 16) < 0.05 for s in scaled),
          f"seconds_256 is the 64x64 render's seconds times 16: {scaled[:3]}")
    size = png_size(os.path.join(out, "convergence.png"))
    wanted = (convergence_script.PLOT_WIDTH, convergence_script.PLOT_HEIGHT)
    check(size == wanted, f"convergence.png is a {wanted[0]}x{wanted[1]} PNG: {size}")
    with open(os.path.join(out, "handout.csv"), newline="") as f:
        handout = list(csv.DictReader(f))
    check(sorted({r["lab"] for r in handout}) == sorted(LABS) and
          all(float(r["relative_rmse"]) > 0 for r in handout),
          f"handout.csv holds the handout's curves of the four labs ({len(handout)} rows)")
    renders = os.listdir(os.path.join(out, "renders"))
    check(len(renders) == 2 * len(rows), "an image and a stats file per render")


def check_bad_input(scratch):
    for spp, words in [("0", "SPP: 0 is outside"), ("'4 x'", "'x' is not a whole number"),
                       ("70000", "SPP: 70000 is outside")]:
        out = os.path.join(scratch, "bad")
        result = run(["sh", "-c", f"{sys.executable} {SCRIPT} --build {args.build} --spp {spp} "
                                  f"--out {out}"])
        lines = result.stderr.strip().splitlines()
        check(result.returncode == 2 and len(lines) == 1 and words in lines[0] and
              not result.stdout and not os.path.exists(out),
              f"convergence.py --spp {spp}: exit 2, one line naming it, nothing written: "
              f"{result.returncode} {lines}")
    build = os.path.join(scratch, "make-build")
    result = run(["make", "--no-print-directory", "convergence", f"BUILD={build}", "SPP=-1"],
                 cwd=args.source)
    ours = [line for line in result.stderr.splitlines() if line.startswith("make convergence:")]
    check(result.returncode == 2 and len(ours) == 1 and "SPP: -1 is outside" in ours[0] and
          not os.path.exists(build),
          f"make convergence SPP=-1: exit 2, one line naming it, nothing written: "
          f"{result.returncode} {ours}")


def main():
    with tempfile.TemporaryDirectory() as scratch:
        check_study(scratch)
        check_bad_input(scratch)
    sys.exit(exit_code())


if __name__ == "__main__":
    main()
