#!/usr/bin/env python3
"""`make convergence`: the error-versus-time plot of the student's labs against a reference.

Usage: convergence.py --build BUILD [--spp "N1 N2 ..."] [--solution] [--out DIR]
       convergence.py --check [the same options]     check them, render nothing, write nothing

Each lab of labs/, in framework/lab_list.txt's order (the viewer's default implementation;
--solution for the reference solutions, which only the instructor's kit has), renders the VI2
Cornell box headless at each spp (`viewer ... --spp N -o N.exr --reference REF --stats N.json`,
seed 0), and the viewer measures the image against the grader's stored reference of the box
(grader/references/, in the student release too: 64x64 pixels, 40 seeds x 128 spp): labs 1-3
against the depth-limited image (maxDepth 3), lab 4 (continueProb 0.8, as graded) against the
unbiased one, as the handout's plot (handouts/figures/convergence.png) measures them. Writes, into
BUILD/convergence/ (printed at the end):

  convergence.csv   one row per lab and spp (the columns: COLUMNS below); cpu_seconds is the
                    render threads' CPU time (--stats), summed over them, and cpu_seconds_256
                    that time scaled to 256x256 pixels, the handout's size, so that the two
                    plots' time axes compare; the wall clock's seconds (and seconds_256) beside
  handout.csv       the handout's curves of the reference solutions (handouts/figures/
                    convergence.csv), in the same columns
  convergence.png   relative RMSE against cpu_seconds_256, log-log: yours, the handout's beside
                    them (dashed), and a slope -1/2 guide line
  renders/          each render's image and --stats file

The time axis is CPU time because other programs on the machine change it little: on a busy
laptop the wall clock's seconds stretch several-fold, and the curves would sit far to the right
of the handout's for no fault of the labs. It is also the same whatever the number of threads.
A render that found the machine busy (--stats' busy_note) is said at the end, in one line.

The reference has its own noise (about that of 5000 spp): above some 500 spp it adds to the
error measured. A sample's noise is higher at 64x64 than at the handout's 256x256 (about 1.5 times
for the reference solutions), so even a correct lab's curve sits above the handout's: compare the
slopes, and the labs' order at equal time. Bad input (spp that are not whole numbers from 1 to 65536) is one line naming
it, exit status 2, and nothing written. Python 3 standard library and gnuplot.
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import time

import headless_viewer

KIT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(KIT, "models", "cornell_box_VI2_Specular.ecs")
REFERENCES = os.path.join(KIT, "grader", "references")
HANDOUT_CSV = os.path.join(KIT, "handouts", "figures", "convergence.csv")
PLOT = os.path.join(KIT, "scripts", "convergence.gp")
DEFAULT_SPP = [4, 8, 16, 32, 64, 128, 256, 512]
HANDOUT_PIXELS = 256 * 256
GRADED_CONTINUE_PROB = 0.8
PLOT_WIDTH, PLOT_HEIGHT = 900, 640
# The plot reads cpu_seconds_256 (6) and relative_rmse (8); the wall clock's figures come last.
COLUMNS = ["lab", "label", "reference", "spp", "cpu_seconds", "cpu_seconds_256",
           "samples_per_cpu_second", "relative_rmse", "rel_mse", "noise", "seconds", "seconds_256",
           "samples_per_second"]
# The words in the plot and the handout's row of the labs the handouts draw.
HANDOUT_LABS = {"branching": ("branching (lab 1)", "branching"),
                "uniform": ("uniform pick (lab 2)", "uniform"),
                "importance": ("importance pick (lab 3)", "importance"),
                "roulette": ("roulette, continueProb 0.8 (lab 4)", "roulette_p08")}
# The labs of the lab list in its order, each with its words in the plot and its handout row:
# a lab the handouts do not draw yet is "NAME (lab N)", without a handout curve.
LABS = [(lab, *HANDOUT_LABS.get(lab, (f"{lab} (lab {number})", None)))
        for number, lab in enumerate(headless_viewer.lab_estimates(), start=1)]


UsageError = headless_viewer.UsageError
RenderFailed = headless_viewer.RenderFailed


def checked_spp(text):
    if not text.strip():
        return DEFAULT_SPP
    values = []
    for word in text.replace(",", " ").split():
        try:
            spp = int(word)
        except ValueError:
            raise UsageError(f"SPP: {word!r} is not a whole number")
        if not 1 <= spp <= 65536:
            raise UsageError(f"SPP: {spp} is outside 1 to 65536")
        values.append(spp)
    return sorted(set(values))


def estimates():
    """{lab: "depth_limited" | "unbiased"}: which reference each lab converges to."""
    return {lab: estimate.replace("-", "_")
            for lab, estimate in headless_viewer.lab_estimates().items()}


def reference_image(kind):
    with open(os.path.join(REFERENCES, "cornell_box_VI2_Specular.json")) as f:
        about = json.load(f)
    return os.path.join(REFERENCES, about[kind]["image"]), about["width"], about["height"]


def render(viewer, lab, spp, solution, reference, size, folder):
    """One headless render against `reference`; returns its --stats as a dict."""
    image, stats = os.path.join(folder, f"{lab}-{spp}.exr"), os.path.join(folder, f"{lab}-{spp}.json")
    options = ["-c", SCENE, "--lab", lab, *(["--solution"] if solution else []),
               "--spp", str(spp), "--size", str(size[0]), str(size[1]), "--seed", "0",
               "--reference", reference]
    if headless_viewer.lab_estimates()[lab] == "unbiased":  # its paths end by roulette
        options += ["--continue-prob", str(GRADED_CONTINUE_PROB)]
    return headless_viewer.render(viewer, options, image, stats,
                                  f"make convergence: the render of {lab} at {spp} spp failed")


def row(lab, label, kind, stats):
    scale = HANDOUT_PIXELS / (stats["width"] * stats["height"])
    return {"lab": lab, "label": label, "reference": kind, "spp": stats["spp"],
            "cpu_seconds": f"{stats['cpu_seconds']:.4g}",
            "cpu_seconds_256": f"{stats['cpu_seconds'] * scale:.4g}",
            "samples_per_cpu_second": round(stats["samples_per_cpu_second"]),
            "relative_rmse": f"{stats['reference']['relative_rmse']:.4g}",
            "rel_mse": f"{stats['reference']['rel_mse']:.4g}",
            "noise": f"{stats['noise']:.4g}",
            "seconds": f"{stats['seconds']:.4g}",
            "seconds_256": f"{stats['seconds'] * scale:.4g}",
            "samples_per_second": round(stats["samples_per_second"])}


def handout_rows():
    """The handout's curves of the reference solutions, in this script's columns (its times
    are already at 256x256)."""
    if not os.path.exists(HANDOUT_CSV):
        return []
    keys = {key: (lab, label) for lab, label, key in LABS if key}
    rows = []
    with open(HANDOUT_CSV, newline="") as f:
        for r in csv.DictReader(f):
            if r["estimator"] not in keys:
                continue
            lab, label = keys[r["estimator"]]
            rows.append({"lab": lab, "label": label, "reference": r["reference"],
                         "spp": r["spp"], "cpu_seconds": r["cpu_seconds"],
                         "cpu_seconds_256": r["cpu_seconds"],
                         "samples_per_cpu_second": r["samples_per_cpu_second"],
                         "relative_rmse": r["relative_rmse"], "rel_mse": "", "noise": r["noise"],
                         "seconds": r["seconds"], "seconds_256": r["seconds"],
                         "samples_per_second": r["samples_per_second"]})
    return rows


def todo_labs():
    """The labs of labs/ with steps still marked PATHLAB_TODO."""
    unfinished = []
    for lab, _, _ in LABS:
        with open(os.path.join(KIT, "labs", lab + ".cpp")) as f:
            if 'PATHLAB_TODO("' in f.read():
                unfinished.append(lab)
    return unfinished


def write_csv(path, rows):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS, lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)


def slope_guide(rows):
    """k of the guide line k / sqrt(t): under every curve, touching the lowest."""
    products = [float(r["relative_rmse"]) * math.sqrt(float(r["cpu_seconds_256"])) for r in rows
                if float(r["relative_rmse"]) > 0 and float(r["cpu_seconds_256"]) > 0]
    return 0.8 * min(products) if products else 0.1


def plot(folder, rows, has_handout, solution, size):
    whose = "the reference solutions here" if solution else "your labs/"
    variables = {"data": "convergence.csv", "handout": "handout.csv" if has_handout else "",
                 "out": "convergence.png", "width": PLOT_WIDTH, "height": PLOT_HEIGHT,
                 "yours": "solution here" if solution else "yours", "guide": slope_guide(rows),
                 "title": f"VI2 Cornell box: error versus CPU time of {whose}, "
                          f"{size[0]}x{size[1]} pixels"}
    definitions = "; ".join(f"{k}='{v}'" if isinstance(v, str) else f"{k}={v}"
                            for k, v in variables.items())
    run = subprocess.run(["gnuplot", "-e", definitions, PLOT], cwd=folder, capture_output=True,
                         text=True)
    if run.returncode != 0:
        raise RenderFailed(run.stderr.strip() + "\nmake convergence: gnuplot could not draw "
                           "convergence.png")


def run_study(viewer, spps, solution, out):
    if not os.access(viewer, os.X_OK):
        raise RenderFailed(f"make convergence: no viewer at {viewer} (make build builds it)")
    if not shutil.which("gnuplot"):
        raise RenderFailed("make convergence: gnuplot is needed for the plot "
                           "(scripts/install-deps.sh installs it)")
    kinds = estimates()
    started = time.monotonic()
    with headless_viewer.output_folder(out) as work:
        renders = os.path.join(work, "renders")
        unfinished = [] if solution else todo_labs()
        if unfinished:
            print(f"make convergence: {', '.join(unfinished)} still have PATHLAB_TODO steps; "
                  "their curves measure the labs as they are")
        print(f"make convergence: {len(LABS)} labs at {' '.join(map(str, spps))} spp against "
              "the grader's references", flush=True)
        rows, notes = [], headless_viewer.RenderNotes()
        for lab, label, _ in LABS:
            reference, width, height = reference_image(kinds[lab])
            for spp in spps:
                stats = render(viewer, lab, spp, solution, reference, (width, height), renders)
                rows.append(row(lab, label, kinds[lab], stats))
                print(f"  {lab} {spp} spp: {stats['seconds']:.3f} s "
                      f"({stats['cpu_seconds']:.3f} s of CPU time), relative RMSE "
                      f"{stats['reference']['relative_rmse']:.4g}", flush=True)
                notes.add(stats)
        if notes.summary("convergence"):
            print(notes.summary("convergence"))
        write_csv(os.path.join(work, "convergence.csv"), rows)
        theirs = handout_rows()
        if theirs:
            write_csv(os.path.join(work, "handout.csv"), theirs)
        plot(work, rows, bool(theirs), solution, (width, height))
    print(f"make convergence: done in {time.monotonic() - started:.0f} s; the plot is "
          f"{os.path.abspath(out)}/convergence.png (convergence.csv, "
          f"{'handout.csv, ' if theirs else ''}renders/ beside it)")


def main(argv):
    parser = headless_viewer.command_parser(
        __doc__.split("\n")[0], "BUILD/convergence",
        "the reference solutions instead of labs/ (the instructor's kit)")
    parser.add_argument("--spp", default="", help="samples per pixel of the renders, apart by "
                        f"spaces (default {' '.join(map(str, DEFAULT_SPP))})")
    args = parser.parse_args(argv)
    return headless_viewer.command_status(
        "convergence", args, lambda: checked_spp(args.spp),
        lambda spps: run_study(os.path.join(args.build, "viewer"), spps, args.solution,
                               args.out or os.path.join(args.build, "convergence")))


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
