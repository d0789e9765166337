#!/usr/bin/env python3
"""make convergence (scripts/convergence.py), ctest label `convergence`: it runs here and in the
student release.

Usage: convergence_test.py --build BUILD --source KIT

Checks, each printing PASS/FAIL (the script exits non-zero if any failed):
1. A tiny study (the labs of labs/ as they are, at 2 and 4 spp, 64x64 against the grader's
   references): exit 0, the plot named at the end; convergence.csv has a row per lab and spp,
   labs 1-3 against the depth-limited reference and labs 4-5 against the unbiased one, the time
   axis by CPU time first (cpu_seconds_256, the plot's x), every figure finite and positive,
   cpu_seconds_256 and seconds_256 the CPU and wall seconds scaled to 256x256, and the samples
   per CPU-second those of the render's samples; convergence.png is a PNG of the plot's size;
   handout.csv holds the handout's curves of the labs it draws, every row of
   handouts/figures/convergence.csv of those labs, its CPU seconds already at 256x256.
2. The rows of made-up renders (the viewer replaced): a render that found the machine busy is
   said in one line after the renders, with how many more did.
3. Bad input (spp that are not whole numbers from 1 to 65536) is one line naming it and exit
   status 2, from the script and from `make convergence`, and writes nothing.
"""
import contextlib
import io
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import LABS, UNBIASED, check, run_in_scratch_folder  # noqa: E402
from png_pixels import png_size  # noqa: E402
from script_tests import (check_make_refuses, check_script_refuses, check_succeeded,  # noqa: E402
                          close, import_script, read_csv, run, script_test_arguments)

args = script_test_arguments()
SCRIPT, convergence_script = import_script(args.source, "convergence")


FIGURES = ["cpu_seconds", "cpu_seconds_256", "samples_per_cpu_second", "relative_rmse", "rel_mse",
           "noise", "seconds", "seconds_256", "samples_per_second"]
# The CSV's numbers have 4 significant digits.
ROUNDING = 2e-3


def check_study(scratch):
    out = os.path.join(scratch, "convergence")
    result = run([sys.executable, SCRIPT, "--build", args.build, "--spp", "4 2", "--out", out])
    if not check_succeeded(result, "a study at 2 and 4 spp"):
        return
    last = result.stdout.splitlines()[-1]
    check(f"the plot is {os.path.abspath(out)}/convergence.png" in last,
          f"the last line names the plot: {last!r}")
    rows = read_csv(os.path.join(out, "convergence.csv"))
    check([(r["lab"], int(r["spp"])) for r in rows] == [(lab, spp) for lab in LABS
                                                         for spp in (2, 4)],
          f"convergence.csv has a row per lab and spp, in order: "
          f"{[(r['lab'], r['spp']) for r in rows]}")
    check(all(r["reference"] == ("unbiased" if r["lab"] in UNBIASED else "depth_limited")
              for r in rows), "labs 1-3 against the depth-limited reference, labs 4 and 5 the "
                              "unbiased")
    header = list(rows[0]) if rows else []
    check(header == convergence_script.COLUMNS and header[5] == "cpu_seconds_256" and
          header[7] == "relative_rmse",
          f"convergence.csv's columns, the plot's x (6) the CPU seconds at 256x256: {header}")
    bad = [(r["lab"], r["spp"], k, r.get(k)) for r in rows for k in FIGURES
           if not (r.get(k) and math.isfinite(float(r[k])) and float(r[k]) > 0)]
    check(not bad, f"every figure finite and positive {bad[:3] if bad else ''}")
    if bad:
        return
    scaled = [(float(r["cpu_seconds_256"]) / float(r["cpu_seconds"]),
               float(r["seconds_256"]) / float(r["seconds"])) for r in rows]
    check(all(close(cpu, 16, ROUNDING) and close(wall, 16, ROUNDING) for cpu, wall in scaled),
          f"cpu_seconds_256 and seconds_256 are the 64x64 render's times 16: {scaled[:3]}")
    rates = [(float(r["samples_per_cpu_second"]), int(r["spp"]) * 64 * 64 / float(r["cpu_seconds"]))
             for r in rows]
    check(all(close(a, b, ROUNDING) for a, b in rates),
          f"samples_per_cpu_second is the samples over cpu_seconds {rates[:3]}")
    size = png_size(os.path.join(out, "convergence.png"))
    wanted = (convergence_script.PLOT_WIDTH, convergence_script.PLOT_HEIGHT)
    check(size == wanted, f"convergence.png is a {wanted[0]}x{wanted[1]} PNG: {size}")
    handout = read_csv(os.path.join(out, "handout.csv"))
    keys = [key for _, _, key in convergence_script.LABS]
    theirs = [r for r in read_csv(convergence_script.HANDOUT_CSV) if r["estimator"] in keys]
    # The labs the handout has a curve of (a later lab has none yet).
    drawn = sorted(lab for lab, _, key in convergence_script.LABS if key)
    check(sorted({r["lab"] for r in handout}) == drawn and len(handout) == len(theirs) and
          all(float(r["relative_rmse"]) > 0 for r in handout),
          f"handout.csv holds the handout's curves of the labs {drawn} ({len(handout)} rows of "
          f"{len(theirs)})")
    check([(float(r["cpu_seconds_256"]), float(r["samples_per_cpu_second"])) for r in handout] ==
          [(float(r["cpu_seconds"]), float(r["samples_per_cpu_second"])) for r in theirs] and
          all(float(r["cpu_seconds_256"]) > 0 and float(r["samples_per_cpu_second"]) > 0
              for r in handout),
          "handout.csv's CPU seconds are the handout's, already at 256x256, with its samples per "
          "CPU-second")
    renders = os.listdir(os.path.join(out, "renders"))
    check(len(renders) == 2 * len(rows), "an image and a stats file per render")


def check_made_up_renders(scratch):
    """run_study on made-up --stats, the viewer replaced: the second lab's renders found the
    machine busy."""
    def made_up(viewer, lab, spp, solution, reference, size, folder):
        busy = "the machine was busy: made up" if lab == "uniform" else ""
        samples = spp * size[0] * size[1]
        return {"width": size[0], "height": size[1], "spp": spp, "cpu_seconds": 0.01 * spp,
                "seconds": 0.02 * spp, "samples_per_cpu_second": samples / (0.01 * spp),
                "samples_per_second": samples / (0.02 * spp), "noise": 1 / spp,
                "reference": {"relative_rmse": 1 / spp, "rel_mse": 1 / spp ** 2},
                "busy_note": busy, "cpu_note": ""}

    out = os.path.join(scratch, "made-up")
    real, convergence_script.render = convergence_script.render, made_up
    said = io.StringIO()
    try:
        with contextlib.redirect_stdout(said):
            convergence_script.run_study(os.path.join(args.build, "viewer"), [2, 4], False, out)
    finally:
        convergence_script.render = real
    lines = said.getvalue().splitlines()
    busy = [line for line in lines if "busy" in line]
    check(busy == ["make convergence: the machine was busy: made up (and in 1 more render(s))"]
          and lines.index(busy[0]) > max(i for i, line in enumerate(lines)
                                         if line.startswith("  ")),
          f"made-up renders: the busy machine said in one line after the renders: {busy}")
    rows = read_csv(os.path.join(out, "convergence.csv"))
    scaled = [(r["cpu_seconds"], r["cpu_seconds_256"], r["seconds_256"]) for r in rows[:2]]
    check(scaled == [("0.02", "0.32", "0.64"), ("0.04", "0.64", "1.28")],
          f"made-up renders: the CPU and wall seconds, each scaled to 256x256: {scaled}")


def check_bad_input(scratch):
    for spp, words in [("0", "SPP: 0 is outside"), ("'4 x'", "'x' is not a whole number"),
                       ("70000", "SPP: 70000 is outside")]:
        check_script_refuses(SCRIPT, args.build, f"--spp {spp}", words, scratch)
    check_make_refuses(args.source, "convergence", ["SPP=-1"], "SPP: -1 is outside", scratch)


def main():
    run_in_scratch_folder(check_study, check_made_up_renders, check_bad_input)


if __name__ == "__main__":
    main()
