#!/usr/bin/env python3
"""`make sweep`: one lab rendered at a range of values of one of its parameters, and plotted.

Usage: sweep.py --build BUILD [--lab LAB] [--param PARAM] [--values "V1 V2 ..."] [--size N]
                [--spp N] [--solution] [--out DIR]
       sweep.py --check [the same options]      check them, render nothing, write nothing

The student's own labs/LAB.cpp (the viewer's default implementation; --solution for the
reference solution, which only the instructor's kit has) is rendered headless on the VI2 Cornell
box, the handouts' scene (veach_plates for glossy-exponent), once per value (`viewer ... --spp N -o VALUE.png --stats VALUE.json`),
at SIZE×SIZE pixels and N samples per pixel, seed 0. PARAM is what the lab lets you choose:

  continue-prob   labs 4-5: Russian roulette's continueProb, values in (0, 1)
  max-depth       labs 1-3: the depth limit, whole numbers from 0
  glossy-exponent lab 5 (a lab that writes a lobe): the Phong exponent of every glossy plate of
                  veach_plates (viewer --glossy-exponent), values above 0, at continueProb 0.8

(each does nothing in the other labs, so asking for it there is refused). Writes, into
BUILD/sweep/LAB-PARAM/ (printed at the end):

  sweep.csv     one row per value (the columns: FIGURE_COLUMNS and RENDER_COLUMNS below)
  sweep.png     samples per CPU-second, noise of one sample and efficiency against the value:
                yours, and the handout's figures of the reference solution beside them. Speed
                and efficiency are by CPU time (the render threads', from --stats), which other
                programs on the machine change little: a busy laptop's wall-clock frame rates
                can fall several times below the handout's and hide the shape to compare
  handout.csv   those handout figures, in the same columns (from handouts/figures/
                roulette_sweep.csv or depth_sweep.csv, at this sweep's image size)
  renders/      each value's image and --stats file

Bad input (an unknown LAB or PARAM, a value out of range) is one line naming it, exit status 2,
and nothing written. Python 3 standard library and gnuplot (scripts/install-deps.sh installs it).
"""
import csv
import math
import os
import shutil
import subprocess
import sys
import time

import headless_viewer

KIT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(KIT, "models", "cornell_box_VI2_Specular.ecs")
GLOSSY_SCENE = os.path.join(KIT, "models", "veach_plates.ecs")
FIGURES = os.path.join(KIT, "handouts", "figures")
PLOT = os.path.join(KIT, "scripts", "sweep.gp")
DEFAULT_SIZE, DEFAULT_SPP = 256, 64
# The plot's size in pixels (scripts/sweep.gp draws three panels side by side).
PLOT_WIDTH, PLOT_HEIGHT = 1500, 480
# After the parameter's own column, the same figures as handout.csv (efficiency per CPU-second:
# 1/(noise² × CPU seconds)), then the render's own, wall-clock ones among them.
FIGURE_COLUMNS = ["samples_per_cpu_second", "rays_per_sample", "noise_per_sample", "efficiency"]
RENDER_COLUMNS = ["noise", "spp", "cpu_seconds", "seconds", "samples_per_second", "frame_rate",
                  "width", "height"]


UsageError = headless_viewer.UsageError


class Parameter:
    """A lab parameter the viewer takes: its option, its CSV column and its range."""

    def __init__(self, option, column, label, estimate, defaults, handout_csv, scene=SCENE,
                 scene_words="the VI2 Cornell box", extra=(), routines=None):
        self.option, self.column, self.label = option, column, label
        self.estimate = estimate        # the labs it matters in (framework/lab_list.txt)
        self.defaults = defaults
        self.handout_csv = handout_csv  # the reference's figures, in handouts/figures/
        self.scene, self.scene_words = scene, scene_words
        self.extra = list(extra)        # further viewer options
        self.routines = routines        # the lab list's fourth field the labs need, if any

    def applies_to(self, estimate, routines):
        """Whether it does something in a lab of this estimate and these routines."""
        if self.routines:
            return routines == self.routines
        return estimate == self.estimate

    def parse(self, text):
        if self.option == "glossy-exponent":
            try:
                n = float(text)
            except ValueError:
                raise UsageError(f"VALUES: {text!r} is not a number (a Phong exponent is above 0)")
            if not 0 < n <= 1e6:
                raise UsageError(f"VALUES: Phong exponent {text} is not above 0 and at most 1e6")
            return n
        if self.option == "continue-prob":
            try:
                q = float(text)
            except ValueError:
                raise UsageError(f"VALUES: {text!r} is not a number (continueProb is in (0, 1))")
            if q == 1:
                raise UsageError("VALUES: continueProb 1 never ends a path; the viewer refuses it "
                                 "(handouts/04-russian-roulette.md, question 5): use values in (0, 1)")
            if not 0 < q < 1:
                raise UsageError(f"VALUES: continueProb {text} is outside (0, 1)")
            return q
        try:
            depth = int(text)
        except ValueError:
            raise UsageError(f"VALUES: {text!r} is not a whole number (max-depth is 0 or more)")
        if depth < 0:
            raise UsageError(f"VALUES: max-depth {depth} is below 0")
        if depth > 1000:
            raise UsageError(f"VALUES: max-depth {depth} is above 1000, the viewer's limit")
        return depth


PARAMETERS = {
    "continue-prob": Parameter("continue-prob", "continue_prob", "continueProb", "unbiased",
                               [0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95],
                               "roulette_sweep.csv"),
    "max-depth": Parameter("max-depth", "max_depth", "maxDepth", "depth-limited",
                           [1, 2, 3, 4, 5, 6, 7, 8], "depth_sweep.csv"),
    "glossy-exponent": Parameter("glossy-exponent", "glossy_exponent", "Phong exponent",
                                 "unbiased", [1, 3, 10, 30, 100, 300, 1000, 3000],
                                 "glossy_exponent_sweep.csv", GLOSSY_SCENE, "veach_plates",
                                 ["--continue-prob", "0.8"], routines="lobe"),
}


class Sweep:
    """What to render: checked options."""

    def __init__(self, lab, parameter, values, size, spp, solution):
        self.lab, self.parameter, self.values = lab, parameter, values
        self.size, self.spp, self.solution = size, spp, solution

    def name(self):
        return f"{self.lab}-{self.parameter.option}"

    def describe(self, value):
        return f"{self.parameter.label} {value:g}"


def whole_number(name, text, default, low, high):
    if text == "":
        return default
    try:
        value = int(text)
    except ValueError:
        raise UsageError(f"{name}={text} is not a whole number")
    if not low <= value <= high:
        raise UsageError(f"{name}={value} is outside {low} to {high}")
    return value


def checked_sweep(args):
    """The sweep the options ask for; UsageError for bad input."""
    labs = headless_viewer.lab_estimates()
    routines = headless_viewer.lab_routines()
    lab = args.lab or "roulette"
    if lab not in labs:
        raise UsageError(f"LAB={lab} is not a lab: {', '.join(labs)}")
    by_estimate = {p.estimate: p for p in PARAMETERS.values() if not p.routines}
    name = args.param or by_estimate[labs[lab]].option
    if name not in PARAMETERS:
        raise UsageError(f"PARAM={name} is not a parameter: continue-prob (labs 4-5), "
                         "max-depth (labs 1-3) or glossy-exponent (lab 5)")
    parameter = PARAMETERS[name]
    if parameter.routines and not parameter.applies_to(labs[lab], routines.get(lab)):
        lobe = ", ".join(name for name, r in routines.items() if r == "lobe")
        raise UsageError(f"PARAM={name} does nothing in lab {lab}: only a lab that samples a "
                         f"glossy lobe ({lobe}) renders glossy plates")
    if parameter.estimate != labs[lab]:
        if name == "continue-prob":
            roulette = ", ".join(name for name, e in labs.items() if e == "unbiased")
            raise UsageError(f"PARAM=continue-prob does nothing in lab {lab}: only {roulette} "
                             f"play Russian roulette; sweep PARAM=max-depth there")
        raise UsageError(f"PARAM=max-depth does nothing in lab {lab}: it has no depth limit "
                         "(handouts/04-russian-roulette.md); sweep PARAM=continue-prob there")
    texts = args.values.replace(",", " ").split()
    values = sorted({parameter.parse(t) for t in texts}) if texts else parameter.defaults
    size = whole_number("SIZE", args.size, DEFAULT_SIZE, 8, 4096)
    spp = whole_number("SPP", args.spp, DEFAULT_SPP, 1, 1 << 20)
    return Sweep(lab, parameter, values, size, spp, args.solution)


def viewer_options(sweep, value, spp, size=None):
    size = size or sweep.size
    return ["-c", sweep.parameter.scene, "--lab", sweep.lab,
            *(["--solution"] if sweep.solution else []), *sweep.parameter.extra,
            f"--{sweep.parameter.option}", f"{value:g}", "--spp", str(spp),
            "--size", str(size), str(size), "--seed", "0"]


RenderFailed = headless_viewer.RenderFailed


def render(viewer, sweep, value, spp, folder, name, size=None):
    """One headless render; returns its --stats as a dict, "wall_seconds" added. The TODO
    warnings are summed up once, before the renders (todo_line)."""
    image, stats = os.path.join(folder, name + ".png"), os.path.join(folder, name + ".json")
    return headless_viewer.render(viewer, viewer_options(sweep, value, spp, size), image, stats,
                                  f"make sweep: the render at {sweep.describe(value)} failed")


def todo_line(sweep):
    """The steps of the student's lab still marked PATHLAB_TODO, as make run lists them."""
    if sweep.solution:
        return None
    with open(os.path.join(KIT, "labs", sweep.lab + ".cpp")) as f:
        steps = [line.split('PATHLAB_TODO("', 1)[1].split('"', 1)[0]
                 for line in f if 'PATHLAB_TODO("' in line]
    if not steps:
        return None
    return (f"make sweep: labs/{sweep.lab}.cpp has steps still to write: {' '.join(steps)}; "
            "the sweep measures the lab as it is")


def estimate_seconds(viewer, sweep, folder):
    """Seconds the sweep should take, from two short probes at its cheapest and dearest values
    (the smallest and the largest: longer paths cost more): each value's start-up, and its time
    per sample per pixel interpolated between theirs. The cost grows faster than linearly with
    continueProb, so this errs on the long side."""
    probe_spp = min(sweep.spp, 4)
    low, high = min(sweep.values), max(sweep.values)
    probes = {}
    for value in sorted({low, high}):
        stats = render(viewer, sweep, value, probe_spp, folder, "probe")
        probes[value] = (max(stats["wall_seconds"] - stats["seconds"], 0),
                         stats["seconds"] / probe_spp)
    total = 0
    for value in sweep.values:
        t = (value - low) / (high - low) if high > low else 0
        start_up, per_spp = [(1 - t) * a + t * b for a, b in zip(probes[low], probes[high])]
        total += start_up + per_spp * sweep.spp
    return total


def cpu_efficiency(stats):
    """1/(noise² × CPU seconds): the efficiency by the work done, not by the wall clock."""
    noise, cpu = stats["noise"], stats["cpu_seconds"]
    return 1 / (noise * noise * cpu) if noise > 0 and cpu > 0 else 0


def figures_row(stats, column, value):
    """One CSV row from a render's --stats."""
    pixels = stats["width"] * stats["height"]
    rays = stats["rays"]["intersect"] + stats["rays"]["occluded"]
    return {column: value,
            "samples_per_cpu_second": round(stats["samples_per_cpu_second"]),
            "rays_per_sample": f"{rays / (stats['spp'] * pixels):.4g}",
            "noise_per_sample": f"{stats['noise'] * math.sqrt(stats['spp']):.4g}",
            "efficiency": f"{cpu_efficiency(stats):.4g}",
            "noise": f"{stats['noise']:.4g}", "spp": stats["spp"],
            "cpu_seconds": f"{stats['cpu_seconds']:.4g}", "seconds": f"{stats['seconds']:.4g}",
            "samples_per_second": round(stats["samples_per_second"]),
            "frame_rate": f"{stats['samples_per_second'] / pixels:.4g}",
            "width": stats["width"], "height": stats["height"]}


def measure(viewer, sweep, folder, report=print):
    """Renders every value into FOLDER; returns the CSV rows."""
    rows, notes = [], headless_viewer.RenderNotes()
    for value in sweep.values:
        stats = render(viewer, sweep, value, sweep.spp, folder, f"{value:g}")
        rows.append(figures_row(stats, sweep.parameter.column, value))
        report(f"  {sweep.describe(value)}: {sweep.spp} spp in {stats['seconds']:.2f} s "
               f"({stats['cpu_seconds']:.2f} s of CPU time), "
               f"{stats['samples_per_cpu_second'] / 1e6:.3g} M samples per CPU-second, "
               f"noise {stats['noise']:.4g}, efficiency {cpu_efficiency(stats):.3g}"
               + (f" ({stats['nonfinite_pixels']} NaN or infinite pixels left out)"
                  if stats.get("nonfinite_pixels") else ""))
        notes.add(stats)
    if notes.summary("sweep"):
        report(notes.summary("sweep"))
    return rows


def handout_rows(sweep):
    """The reference solution's figures from the handouts, at this sweep's image size: a
    render's efficiency 1/(noise² × CPU s) is samples per CPU-second ÷ (pixels × noise of one
    sample²), so it is recomputed for these pixels from the handout's samples per CPU-second and
    noise of one sample. [] when the handouts have none for this lab."""
    path = os.path.join(FIGURES, sweep.parameter.handout_csv)
    if not os.path.exists(path):
        return []
    pixels = sweep.size * sweep.size
    rows = []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row.get("lab", sweep.lab) != sweep.lab:
                continue
            rate, sigma = float(row["samples_per_cpu_second"]), float(row["noise_per_sample"])
            rows.append({sweep.parameter.column: row[sweep.parameter.column],
                         "samples_per_cpu_second": round(rate),
                         "rays_per_sample": row["rays_per_sample"],
                         "noise_per_sample": row["noise_per_sample"],
                         "efficiency": f"{rate / (pixels * sigma * sigma):.4g}"})
    return rows


def write_csv(path, rows, columns):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns, lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)


def plot(sweep, folder, has_handout):
    whose = "the reference solution" if sweep.solution else f"your labs/{sweep.lab}.cpp"
    title = (f"{whose} on {sweep.parameter.scene_words}, {sweep.size}x{sweep.size} pixels, "
             f"{sweep.spp} samples per pixel each")
    exponent = sweep.parameter.option == "glossy-exponent"
    variables = {"data": "sweep.csv", "handout": "handout.csv" if has_handout else "",
                 "out": "sweep.png", "xlabel": sweep.parameter.label, "title": title,
                 "yours": "the reference solution here" if sweep.solution else "yours",
                 "pixels": f"{sweep.size}x{sweep.size}", "width": PLOT_WIDTH,
                 "height": PLOT_HEIGHT,
                 "logx": 1 if exponent else 0,
                 "xmin": 0 if sweep.parameter.option == "continue-prob"
                 else min(sweep.values) / 1.5 if exponent else min(sweep.values) - 0.5,
                 "xmax": 1 if sweep.parameter.option == "continue-prob"
                 else max(sweep.values) * 1.5 if exponent else max(sweep.values) + 0.5}
    definitions = "; ".join(f"{k}='{v}'" if isinstance(v, str) else f"{k}={v}"
                            for k, v in variables.items())
    run = subprocess.run(["gnuplot", "-e", definitions, PLOT], cwd=folder, capture_output=True,
                         text=True)
    if run.returncode != 0:
        raise RenderFailed(run.stderr.strip() + "\nmake sweep: gnuplot could not draw sweep.png")


def run_sweep(viewer, sweep, out):
    """Renders, writes and plots into OUT (replaced only once all of it is made)."""
    if not os.access(viewer, os.X_OK):
        raise RenderFailed(f"make sweep: no viewer at {viewer} (make build builds it)")
    if not shutil.which("gnuplot"):
        raise RenderFailed("make sweep: gnuplot is needed for the plots "
                           "(scripts/install-deps.sh installs it)")
    with headless_viewer.output_folder(out) as work:
        renders = os.path.join(work, "renders")
        todo = todo_line(sweep)
        if todo:
            print(todo)
        seconds = estimate_seconds(viewer, sweep, work)
        whose = "reference solution" if sweep.solution else f"labs/{sweep.lab}.cpp"
        print(f"make sweep: {len(sweep.values)} renders of {whose} at {sweep.size}x{sweep.size} "
              f"pixels, {sweep.spp} spp each, {sweep.parameter.label} "
              f"{' '.join(f'{v:g}' for v in sweep.values)}: about {max(seconds, 1):.0f} s",
              flush=True)
        for name in ("probe.png", "probe.json"):
            os.remove(os.path.join(work, name))
        started = time.monotonic()
        rows = measure(viewer, sweep, renders, lambda line: print(line, flush=True))
        columns = [sweep.parameter.column] + FIGURE_COLUMNS
        write_csv(os.path.join(work, "sweep.csv"), rows, columns + RENDER_COLUMNS)
        reference = handout_rows(sweep)
        if reference:
            write_csv(os.path.join(work, "handout.csv"), reference, columns)
        else:
            print(f"make sweep: the handouts have no figures of lab {sweep.lab}'s "
                  f"{sweep.parameter.label} (handouts/figures/{sweep.parameter.handout_csv}); "
                  "the plot shows yours alone")
        plot(sweep, work, bool(reference))
    best = max(rows, key=lambda r: float(r["efficiency"]))
    # Efficiency counts a render's own noise, not its bias: a lower maxDepth is quicker and
    # quieter, and further from the unbiased image.
    bias = (" (by its noise alone: a lower maxDepth is also more biased, which efficiency does "
            "not count)" if sweep.parameter.column == "max_depth" else "")
    print(f"make sweep: done in {time.monotonic() - started:.0f} s; most efficient here: "
          f"{sweep.parameter.label} {best[sweep.parameter.column]:g}{bias}")
    made = ["sweep.csv", "sweep.png"] + (["handout.csv"] if reference else []) + ["renders/"]
    print(f"make sweep: the figures are in {os.path.abspath(out)}/ ({', '.join(made)})")


def main(argv):
    parser = headless_viewer.command_parser(
        __doc__.split("\n")[0], "BUILD/sweep/LAB-PARAM",
        "the reference solution instead of labs/ (the instructor's kit)")
    parser.add_argument("--lab", default="", help=" | ".join(headless_viewer.lab_estimates()) +
                        " (default roulette)")
    parser.add_argument("--param", default="", help="continue-prob (lab 4) or max-depth (labs "
                                                    "1-3); default: the lab's")
    parser.add_argument("--values", default="", help="the values, apart by spaces or commas")
    parser.add_argument("--size", default="", help=f"pixels per side (default {DEFAULT_SIZE})")
    parser.add_argument("--spp", default="", help=f"samples per pixel (default {DEFAULT_SPP})")
    args = parser.parse_args(argv)
    return headless_viewer.command_status(
        "sweep", args, lambda: checked_sweep(args),
        lambda sweep: run_sweep(os.path.join(args.build, "viewer"), sweep,
                                args.out or os.path.join(args.build, "sweep", sweep.name())))


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
