#!/usr/bin/env python3
"""make sweep (scripts/sweep.py), ctest label `sweep`: it runs here and in the student release.

Usage: sweep_test.py --build BUILD --source KIT

Checks, each printing PASS/FAIL (the script exits non-zero if any failed):
1. A tiny sweep of each parameter (16×16 pixels, 2 spp, two values) on the labs of labs/ as they
   are: exit 0, a time estimate line before the renders and the output folder named at the end;
   sweep.csv has one row per value, the value first, then the figures by CPU time
   (samples_per_cpu_second, ..., efficiency), every figure finite and positive, the efficiency
   1/(noise² × CPU seconds) and the samples per CPU-second and the frame rate those of the
   render's samples, within the CSV's rounding; sweep.png is a PNG of the plot's size;
   handout.csv holds the handout's figures of that lab, every row of
   handouts/figures/roulette_sweep.csv or depth_sweep.csv, with its samples per CPU-second and
   the efficiency recomputed for 16×16 pixels.
2. The figures of made-up renders (the viewer replaced): the efficiency is by CPU time, not by
   the wall clock, and a render that found the machine busy is said in one line after the
   renders, with how many more did.
3. Bad input (an unknown LAB or PARAM, a parameter the lab does not have, a value out of range,
   a size that is not a number) is one line naming it and exit status 2, from the script and
   from `make sweep`, and writes nothing: no output folder, no build folder.
"""
import math
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import LOBE, check, exit_code  # noqa: E402
from png_pixels import png_size  # noqa: E402
from script_tests import (check_make_refuses, check_script_refuses, check_succeeded,  # noqa: E402
                          close, import_script, read_csv, run, script_test_arguments)

args = script_test_arguments()
SWEEP, sweep_script = import_script(args.source, "sweep")

FIGURES = ["samples_per_cpu_second", "rays_per_sample", "noise_per_sample", "efficiency", "noise",
           "cpu_seconds", "seconds", "samples_per_second", "frame_rate"]
# The CSV's numbers have 4 significant digits: a figure computed from two or three of them
# agrees with its own column to a few parts in a thousand.
ROUNDING = 3e-3


def check_sweep(scratch, lab, param, values, column):
    out = os.path.join(scratch, f"{lab}-{param}")
    result = run([sys.executable, SWEEP, "--build", args.build, "--lab", lab, "--param", param,
                  "--values", values, "--size", "16", "--spp", "2", "--out", out])
    name = f"sweep of {lab}'s {param} at {values}"
    if not check_succeeded(result, name):
        return
    lines = result.stdout.splitlines()
    estimate = next((i for i, line in enumerate(lines) if re.search(r": about \d+ s$", line)),
                    None)
    first_render = next((i for i, line in enumerate(lines) if line.startswith("  ")), None)
    check(estimate is not None and first_render is not None and estimate < first_render,
          f"{name}: a time estimate line before the renders")
    check(f"the figures are in {os.path.abspath(out)}/" in lines[-1],
          f"{name}: the last line names the output folder: {lines[-1]!r}")
    rows = read_csv(os.path.join(out, "sweep.csv"))
    wanted = [float(v) for v in values.split()]
    check([float(r[column]) for r in rows] == wanted,
          f"{name}: sweep.csv has a row per value, in column {column}")
    header = list(rows[0]) if rows else []
    check(header[:1 + len(sweep_script.FIGURE_COLUMNS)] == [column] + sweep_script.FIGURE_COLUMNS
          and "samples_per_cpu_second" in header,
          f"{name}: sweep.csv's columns start with the value and the figures by CPU time {header}")
    bad = [(r[column], k, r.get(k)) for r in rows for k in FIGURES
           if not (r.get(k) and math.isfinite(float(r[k])) and float(r[k]) > 0)]
    check(not bad, f"{name}: every figure finite and positive {bad[:3] if bad else ''}")
    if bad:
        return
    samples = [int(r["spp"]) * int(r["width"]) * int(r["height"]) for r in rows]
    efficiency = [(float(r["efficiency"]), 1 / (float(r["noise"]) ** 2 * float(r["cpu_seconds"])))
                  for r in rows]
    check(all(close(a, b, ROUNDING) for a, b in efficiency),
          f"{name}: efficiency is 1/(noise² × CPU seconds) {efficiency}")
    rates = [(float(r["samples_per_cpu_second"]), n / float(r["cpu_seconds"]))
             for r, n in zip(rows, samples)]
    check(all(close(a, b, ROUNDING) for a, b in rates),
          f"{name}: samples_per_cpu_second is the samples over cpu_seconds {rates}")
    frames = [(float(r["frame_rate"]), float(r["samples_per_second"]) / (n / int(r["spp"])))
              for r, n in zip(rows, samples)]
    check(all(close(a, b, ROUNDING) for a, b in frames),
          f"{name}: frame_rate is the wall clock's samples/s over the pixels {frames}")
    size = png_size(os.path.join(out, "sweep.png"))
    check(size == (sweep_script.PLOT_WIDTH, sweep_script.PLOT_HEIGHT),
          f"{name}: sweep.png is a {sweep_script.PLOT_WIDTH}x{sweep_script.PLOT_HEIGHT} PNG: {size}")
    renders = sorted(os.listdir(os.path.join(out, "renders")))
    check(len(renders) == 2 * len(wanted), f"{name}: an image and a stats file per value")
    parameter = sweep_script.PARAMETERS[param]
    figures = os.path.join(sweep_script.FIGURES, parameter.handout_csv)
    if not os.path.exists(figures):
        # The handouts have no figures of it: the plot shows the student's alone, and says so.
        check(not os.path.exists(os.path.join(out, "handout.csv")) and
              any("the plot shows yours alone" in line for line in lines),
              f"{name}: no handout.csv, and the output says the plot shows the student's alone")
        return
    handout = read_csv(os.path.join(out, "handout.csv"))
    theirs = [r for r in read_csv(figures) if r.get("lab", lab) == lab]
    check(len(handout) >= 2 and len(handout) == len(theirs) and
          [float(r[column]) for r in handout] == [float(r[column]) for r in theirs],
          f"{name}: handout.csv holds the handout's {len(theirs)} rows of {lab} "
          f"({len(handout)} rows)")
    recomputed = [(float(r["efficiency"]), float(r["samples_per_cpu_second"]) /
                   (16 * 16 * float(r["noise_per_sample"]) ** 2)) for r in handout]
    check(all(float(r["samples_per_cpu_second"]) > 0 for r in handout) and
          all(close(a, b, ROUNDING) for a, b in recomputed),
          f"{name}: handout.csv has the handout's samples per CPU-second and their efficiency "
          f"at 16x16 pixels {recomputed[:2]}")


def check_made_up_renders(scratch):
    """measure() on made-up --stats: two renders, one on a busy machine, at half the CPU time of
    their wall time on 2 threads' cores."""
    renders = iter([
        {"busy_note": "", "cpu_note": "", "cpu_seconds": 0.5, "seconds": 0.25},
        {"busy_note": "the machine was busy: made up", "cpu_note": "", "cpu_seconds": 0.5,
         "seconds": 1.0}])

    def made_up(viewer, sweep, value, spp, folder, name, size=None):
        stats = next(renders)
        samples = spp * 16 * 16
        return dict(stats, width=16, height=16, spp=spp, noise=0.5,
                    rays={"intersect": samples, "occluded": samples},
                    samples_per_cpu_second=samples / stats["cpu_seconds"],
                    samples_per_second=samples / stats["seconds"])

    sweep = sweep_script.Sweep("roulette", sweep_script.PARAMETERS["continue-prob"], [0.2, 0.8],
                               16, 2, solution=False)
    real, sweep_script.render = sweep_script.render, made_up
    said = []
    try:
        rows = sweep_script.measure("viewer", sweep, scratch, said.append)
    finally:
        sweep_script.render = real
    check([float(r["efficiency"]) for r in rows] == [8, 8],
          f"made-up renders: efficiency 1/(0.5² × 0.5 CPU-s) = 8 whatever their wall time: "
          f"{[r['efficiency'] for r in rows]}")
    check([r["samples_per_cpu_second"] for r in rows] == [1024, 1024] and
          [r["samples_per_second"] for r in rows] == [2048, 512],
          "made-up renders: samples per CPU-second from the CPU time, samples/s from the wall "
          f"clock's: {[(r['samples_per_cpu_second'], r['samples_per_second']) for r in rows]}")
    check(said[-1:] == ["make sweep: the machine was busy: made up"],
          f"made-up renders: the busy machine said in one line after the renders: {said[-1:]}")


def check_bad_input(scratch):
    cases = [("--lab nolab", "LAB=nolab"),
             ("--lab roulette --param depth", "PARAM=depth"),
             ("--lab roulette --param max-depth", "PARAM=max-depth does nothing in lab roulette"),
             ("--lab uniform --param continue-prob", "PARAM=continue-prob does nothing"),
             ("--lab roulette --param glossy-exponent",
              "PARAM=glossy-exponent does nothing in lab roulette: only a lab that samples a "
              f"glossy lobe ({', '.join(LOBE)})"),
             ("--lab glossy --param glossy-exponent --values 0", "Phong exponent 0 is not above 0"),
             ("--lab roulette --values 0", "continueProb 0 is outside"),
             ("--lab roulette --values '0.5 1'", "continueProb 1 never ends"),
             ("--lab roulette --values 1.5", "continueProb 1.5 is outside"),
             ("--lab branching --values -1", "max-depth -1 is below 0"),
             ("--lab importance --values 2.5", "'2.5' is not a whole number"),
             ("--size big", "SIZE=big")]
    for options, words in cases:
        check_script_refuses(SWEEP, args.build, options, words, scratch)
    # Through make: the options are checked before anything is configured or built.
    for variables, words in [(["LAB=nolab"], "LAB=nolab"),
                             (["LAB=roulette", "VALUES=0.2 2"], "continueProb 2 is outside"),
                             (["LAB=branching", "PARAM=max-depth", "VALUES=-3"], "below 0")]:
        check_make_refuses(args.source, "sweep", variables, words, scratch)


def main():
    with tempfile.TemporaryDirectory(prefix="pathlab-sweep-test-") as scratch:
        check_sweep(scratch, "roulette", "continue-prob", "0.2 0.8", "continue_prob")
        check_sweep(scratch, "branching", "max-depth", "1 3", "max_depth")
        check_sweep(scratch, "glossy", "glossy-exponent", "10 100", "glossy_exponent")
        check_made_up_renders(scratch)
        check_bad_input(scratch)
    return exit_code()


if __name__ == "__main__":
    sys.exit(main())
