#!/usr/bin/env python3
"""Makes the handouts' figures, and the numbers behind them, from the reference solutions.

Usage: make_figures.py --build BUILD [--quick]
       make_figures.py --blocks-only

Everything is measured on the VI2 Cornell box with BUILD/viewer: headless renders (-o FILE.pfm
--stats FILE.json) for images, errors and timings, and the window under a virtual X server
(Xvfb) for the frame rate and noise figure a student reads off the panel.

Render time is CPU time: the render threads' CPU-seconds that --stats measures (cpu_seconds),
summed over the threads, which other programs on the machine change little, where the wall
clock's seconds swing several-fold on a busy machine. Time budgets are CPU-seconds (on an idle
machine with T render threads, a budget of B CPU-seconds takes about B/T seconds of wall time),
and every efficiency is per CPU-second. The wall-clock figures are kept beside them (seconds,
samples_per_second), and the window's frame rate, what a student waits for, is the wall
clock's. Writes into handouts/figures/ (each plot beside the .csv of its numbers):

  equal_time_LAB.png, equal_time.json   one image per estimator, all given the same CPU time
  direct_light_only.png                 what the stubs render: emission and direct light only
  convergence.png, convergence.csv      relative RMSE against a high-spp reference versus CPU
                                        seconds of rendering, beside each render's own noise
                                        figure
  estimators.csv                        samples per CPU-second, the window's frame rate and
                                        samples per CPU-second, noise and efficiency per estimator
  roulette_sweep.png, roulette_sweep.csv
                                        samples per CPU-second, relative RMSE at equal CPU time
                                        and efficiency 1/(relative MSE * CPU seconds) over
                                        continueProb
  depth_sweep.csv                       labs 1-3 over maxDepth, measured as `make sweep`
                                        measures a student's lab (scripts/sweep.py), whose plot
                                        draws these beside the student's

Errors are relative, as the viewer's noise figure is (framework/include/pathlab/images/image_noise.h):
an RMSE over the reference image's mean radiance. The noise figure estimates that same relative
RMSE from a render's own samples, so the two columns of convergence.csv can be compared.
  references.json, run.json             the two references, and the machine and its load (how
                                        many renders found it busy, and the render threads'
                                        share of their cores)

and rewrites the handouts' generated blocks (between "<!-- BEGIN generated: NAME -->" and
"<!-- END generated: NAME -->") with the new numbers. Seeds are fixed: apart from timing, a run
renders the same images. --quick renders tiny versions into a scratch folder, to try the script;
--only-depth-sweep remakes depth_sweep.csv alone (a few minutes), leaving the rest as it is.

Python 3 standard library, gnuplot and Xvfb only.
"""
import argparse
import csv
import json
import math
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pfm import mean_squared_error, read_pfm  # noqa: E402
from viewer_runs import Viewer, start_xvfb, window_measurement  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import sweep as student_sweep  # noqa: E402

TOOLS = os.path.dirname(os.path.abspath(__file__))
HANDOUTS = os.path.dirname(TOOLS)
SOURCE = os.path.dirname(HANDOUTS)
SCENE = os.path.join(SOURCE, "models", "cornell_box_VI2_Specular.ecs")


class Estimator:
    """One lab's reference solution with its parameters, and the image it converges to."""

    def __init__(self, key, lab, label, reference, continue_prob=None):
        self.key, self.lab, self.label = key, lab, label
        self.reference = reference  # "depth_limited" (labs 1-3, maxDepth 3) or "unbiased"
        self.continue_prob = continue_prob


ESTIMATORS = [
    Estimator("branching", "branching", "branching (lab 1)", "depth_limited"),
    Estimator("uniform", "uniform", "uniform pick (lab 2)", "depth_limited"),
    Estimator("importance", "importance", "importance pick (lab 3)", "depth_limited"),
    Estimator("roulette", "roulette", "roulette, continueProb 0.1 (lab 4's default)", "unbiased",
              0.1),
    Estimator("roulette_p08", "roulette", "roulette, continueProb 0.8 (as graded)", "unbiased",
              0.8),
]

# Budgets are CPU-seconds over all render threads: on the kit's 2 cores, idle, each takes about
# half as many seconds of wall time.
FULL = {
    "study_size": 256,           # pixels per side of the convergence study and the sweep
    "reference_spp": 2048,       # samples per pixel of the two references
    "budgets_cpu_seconds": [0.5, 1, 2, 4, 8, 16],  # the convergence study's render times
    "sweep": [0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9],
    "sweep_budget_cpu_seconds": 6.0,  # per sweep render
    "sweep_seeds": 2,            # independent renders per continueProb, MSE averaged
    "depth_sweep": [1, 2, 3, 4, 5, 6, 7, 8],  # maxDepth values of labs 1-3
    "depth_sweep_spp": student_sweep.DEFAULT_SPP,  # as make sweep renders a student's lab
    "depth_sweep_rounds": 3,     # renders per value; the median samples per CPU-second is kept
    "image_size": 512,           # the equal-time images
    "image_budget_cpu_seconds": 16.0,
    "window_size": 512,          # the frame-rate table: the window as a student sees it
    "window_frames": [64, 256],  # the panel is read after these frames
}
QUICK = dict(FULL, study_size=32, reference_spp=64, budgets_cpu_seconds=[0.04, 0.1],
             sweep_budget_cpu_seconds=0.1, sweep_seeds=1, depth_sweep=[1, 2], depth_sweep_spp=2,
             depth_sweep_rounds=2, image_size=48, image_budget_cpu_seconds=0.1, window_size=64,
             window_frames=[4, 16])

REFERENCE_Q = 0.8        # continueProb of the unbiased reference: finite variance on this scene
REFERENCE_SEEDS = {"depth_limited": 900001, "unbiased": 900002}


def mean3(values):
    return sum(values) / len(values)


def make_references(viewer, p):
    """The images labs 1-3 (maxDepth 3) and lab 4 (no depth limit) converge to, each with the
    variance of its own pixel means, which the error measures subtract."""
    references = {}
    for kind, lab, q in [("depth_limited", "importance", None),
                         ("unbiased", "roulette", REFERENCE_Q)]:
        stats = viewer.render(f"reference_{kind}", lab, p["reference_spp"], p["study_size"],
                              REFERENCE_SEEDS[kind], continue_prob=q)
        stats["pixels"] = read_pfm(stats["image"])
        stats["variance_of_mean"] = mean3(stats["mean_variance"]) / stats["spp"]
        stats["brightness"] = mean3(stats["mean_radiance"])  # what errors are relative to
        references[kind] = stats
        print(f"reference {kind}: {lab} {stats['spp']} spp, {stats['seconds']:.1f} s", flush=True)
    return references


def error_against(stats, reference):
    """MSE of an image against a reference, minus the reference's own noise: for independent
    renders E[(X - R)^2] = E[(X - mu)^2] + Var(R), so this estimates the image's MSE alone."""
    raw = mean_squared_error(read_pfm(stats["image"]), reference["pixels"])
    return max(raw - reference["variance_of_mean"], 1e-12), raw


def relative(mse, reference):
    """An MSE relative to the reference image's brightness, squared: what noise² estimates."""
    return mse / reference["brightness"] ** 2


def spp_for(budget_cpu_seconds, samples_per_cpu_second, size):
    return max(1, round(budget_cpu_seconds * samples_per_cpu_second / (size * size)))


def convergence_study(viewer, p, references):
    """Each estimator rendered for each budget of CPU-seconds, with spp from its measured
    samples per CPU-second. The estimators take turns at each budget, so a change in the
    machine's load, which CPU time mostly hides, hits all alike anyway."""
    throughput = {e.key: viewer.samples_per_cpu_second(e.lab, p["study_size"], e.continue_prob)
                  for e in ESTIMATORS}
    rows = []
    for step, budget in enumerate(p["budgets_cpu_seconds"]):
        for index, e in enumerate(ESTIMATORS):
            spp = spp_for(budget, throughput[e.key], p["study_size"])
            stats = viewer.render(f"convergence_{e.key}_{step}", e.lab, spp, p["study_size"],
                                  100 + 10 * index + step, continue_prob=e.continue_prob)
            reference = references[e.reference]
            mse, raw = error_against(stats, reference)
            rows.append({"estimator": e.key, "label": e.label, "reference": e.reference,
                         "budget_cpu_seconds": budget, "spp": spp,
                         "cpu_seconds": round(stats["cpu_seconds"], 4),
                         "seconds": round(stats["seconds"], 4),
                         "samples_per_cpu_second": round(stats["samples_per_cpu_second"]),
                         "samples_per_second": round(stats["samples_per_second"]),
                         "rays_per_sample": round(rays_per_sample(stats), 3),
                         "noise": round(stats["noise"], 5),
                         "noise_per_sample": round(stats["noise"] * math.sqrt(spp), 4),
                         "relative_rmse": round(math.sqrt(relative(mse, reference)), 6),
                         "rmse": round(math.sqrt(mse), 6), "rmse_uncorrected": round(math.sqrt(raw), 6),
                         "efficiency": round(1 / (relative(mse, reference) * stats["cpu_seconds"]), 4)})
            print(f"convergence {e.key} {budget} CPU-s: {spp} spp in {stats['cpu_seconds']:.2f} "
                  f"CPU-s ({stats['seconds']:.2f} s), relative RMSE "
                  f"{rows[-1]['relative_rmse']:.4f}, noise {stats['noise']:.4f}", flush=True)
    # One estimator's rows together, in time order: the plot draws each as one line.
    order = {e.key: i for i, e in enumerate(ESTIMATORS)}
    return sorted(rows, key=lambda r: (order[r["estimator"]], r["budget_cpu_seconds"]))


def rays_per_sample(stats):
    rays = stats["rays"]["intersect"] + stats["rays"]["occluded"]
    return rays / (stats["spp"] * stats["width"] * stats["height"])


def roulette_sweep(viewer, p, references):
    """Lab 4's solution at each continueProb for the same CPU time, SWEEP_SEEDS renders each;
    the values take turns, so a change in the machine's load hits all alike."""
    sweep = p["sweep"]
    spp = {q: spp_for(p["sweep_budget_cpu_seconds"],
                      viewer.samples_per_cpu_second("roulette", p["study_size"], continue_prob=q),
                      p["study_size"]) for q in sweep}
    renders = {q: [] for q in sweep}
    for s in range(p["sweep_seeds"]):
        for index, q in enumerate(sweep):
            renders[q].append(viewer.render(f"sweep_{q:g}_{s}", "roulette", spp[q],
                                            p["study_size"], 200 + 10 * index + s, continue_prob=q))
    rows = []
    reference = references["unbiased"]
    for q in sweep:
        runs = renders[q]
        mse = relative(mean3([error_against(r, reference)[0] for r in runs]), reference)
        cpu_seconds = mean3([r["cpu_seconds"] for r in runs])
        rows.append({"continue_prob": q, "spp": spp[q], "cpu_seconds": round(cpu_seconds, 4),
                     "seconds": round(mean3([r["seconds"] for r in runs]), 4),
                     "samples_per_cpu_second": round(mean3([r["samples_per_cpu_second"] for r in runs])),
                     "samples_per_second": round(mean3([r["samples_per_second"] for r in runs])),
                     "rays_per_sample": round(mean3([rays_per_sample(r) for r in runs]), 3),
                     "noise_per_sample": round(mean3([r["noise"] * math.sqrt(spp[q]) for r in runs]), 4),
                     "relative_rmse": round(math.sqrt(mse), 6),
                     "efficiency": round(1 / (mse * cpu_seconds), 4)})
        print(f"sweep continueProb {q}: {spp[q]} spp in {cpu_seconds:.2f} CPU-s, relative RMSE "
              f"{math.sqrt(mse):.4f}", flush=True)
    return rows


def depth_sweep(viewer, p):
    """The reference solutions of labs 1-3 at each maxDepth, rendered and measured as `make
    sweep` renders a student's lab (the same size, spp, seed and figures), so that its plot puts
    the two side by side. The images, and so the noise, are the same in every round; of the
    timings, each value keeps its round of median samples per CPU-second. The rounds take turns
    over all the labs, so a change in the machine's load hits all alike."""
    labs = [lab for lab, estimate in student_sweep.headless_viewer.lab_estimates().items()
            if estimate == "depth-limited"]
    rounds = {lab: [] for lab in labs}
    for turn in range(p["depth_sweep_rounds"]):
        for lab in labs:
            sweep = student_sweep.Sweep(lab, student_sweep.PARAMETERS["max-depth"],
                                        p["depth_sweep"], p["study_size"], p["depth_sweep_spp"],
                                        solution=True)
            rounds[lab].append(student_sweep.measure(
                viewer.executable, sweep, viewer.work,
                lambda line: print(f"depth sweep {lab}, round {turn + 1}:{line}", flush=True)))
    rows = []
    for lab in labs:
        for index in range(len(p["depth_sweep"])):
            runs = sorted((r[index] for r in rounds[lab]),
                          key=lambda r: float(r["samples_per_cpu_second"]))
            rows.append({"lab": lab, **runs[len(runs) // 2]})
    return rows


def window_table(viewer, p):
    """Frame rate, samples per CPU-second and noise as the window's panel shows them, under a
    virtual X server."""
    if not shutil.which("Xvfb"):
        raise SystemExit("make_figures: Xvfb is needed for the frame-rate table "
                         "(scripts/install-deps.sh installs it)")
    server, display = start_xvfb()
    try:
        return {e.key: window_measurement(viewer, display, e.lab, p["window_size"],
                                          p["window_frames"], e.continue_prob)
                for e in ESTIMATORS}
    finally:
        server.terminate()
        server.wait()


def equal_time_images(viewer, p, figures):
    """One image per estimator, each given the same CPU time (spp from samples per CPU-second
    measured just before, at the images' size)."""
    images = {}
    for index, e in enumerate(ESTIMATORS):
        throughput = viewer.samples_per_cpu_second(e.lab, p["image_size"], e.continue_prob)
        spp = spp_for(p["image_budget_cpu_seconds"], throughput, p["image_size"])
        stats = viewer.render(f"equal_time_{e.key}", e.lab, spp, p["image_size"], 300 + index,
                              continue_prob=e.continue_prob, extension="png")
        shutil.copyfile(stats["image"], os.path.join(figures, f"equal_time_{e.key}.png"))
        images[e.key] = {"label": e.label, "spp": spp,
                         "cpu_seconds": round(stats["cpu_seconds"], 3),
                         "seconds": round(stats["seconds"], 3),
                         "samples_per_cpu_second": round(stats["samples_per_cpu_second"]),
                         "size": p["image_size"], "seed": 300 + index}
    # The stubs before any TODO is done: emission seen by the camera plus direct light.
    stats = viewer.render("direct_light_only", "branching", 64, p["image_size"], 399, max_depth=0,
                          extension="png")
    shutil.copyfile(stats["image"], os.path.join(figures, "direct_light_only.png"))
    images["direct_light_only"] = {"label": "--max-depth 0: emission and direct light only",
                                   "spp": 64, "cpu_seconds": round(stats["cpu_seconds"], 3),
                                   "seconds": round(stats["seconds"], 3),
                                   "size": p["image_size"], "seed": 399}
    return images


def write_csv(path, rows):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]), lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)


def write_json(path, value):
    with open(path, "w") as f:
        json.dump(value, f, indent=2)
        f.write("\n")


def gnuplot(script, figures, **variables):
    """Runs TOOLS/SCRIPT in FIGURES with the given variables (strings are quoted)."""
    definitions = "; ".join(f"{k}='{v}'" if isinstance(v, str) else f"{k}={v}"
                            for k, v in variables.items())
    subprocess.run(["gnuplot", "-e", definitions, os.path.join(TOOLS, script)], cwd=figures,
                   check=True)


def depth_limit_bias(references):
    """Relative RMSE between the depth-limited and the unbiased image, without the references'
    noise: the error labs 1-3 keep however long they run, if the unbiased image is the goal."""
    raw = mean_squared_error(references["depth_limited"]["pixels"],
                             references["unbiased"]["pixels"])
    noise = sum(r["variance_of_mean"] for r in references.values())
    return math.sqrt(relative(max(raw - noise, 0.0), references["unbiased"]))


def slope_guide(convergence):
    """k for the plot's k/sqrt(t) line: half of lab 3's typical RMSE*sqrt(t), t in CPU-seconds,
    so the line runs parallel to, and below, the curves of unbiased estimators with finite
    variance."""
    products = [r["relative_rmse"] * math.sqrt(r["cpu_seconds"]) for r in convergence
                if r["estimator"] == "importance"]
    return 0.5 * statistics.median(products)


def window_cpu_efficiency(panel, pixels):
    """1/(noise² × CPU seconds) of the window after panel["spp"] frames: its CPU seconds are the
    samples it rendered over its samples per CPU-second."""
    cpu_seconds = panel["spp"] * pixels / panel["samples_per_cpu_second"]
    return 1 / (panel["noise"] ** 2 * cpu_seconds)


def estimator_rows(convergence, window, p):
    """One row per estimator: speed from the convergence study's headless renders, and what the
    window's panel showed after each of p["window_frames"] frames. efficiency is per
    CPU-second, efficiency_wall the panel's own (per second of wall time rendering)."""
    early, late = p["window_frames"]
    pixels = p["window_size"] ** 2
    rows = []
    for e in ESTIMATORS:
        mine = [r for r in convergence if r["estimator"] == e.key]
        panel = window[e.key]
        rows.append({"estimator": e.key, "label": e.label,
                     "samples_per_cpu_second": round(statistics.median(r["samples_per_cpu_second"] for r in mine)),
                     "samples_per_second": round(statistics.median(r["samples_per_second"] for r in mine)),
                     "rays_per_sample": mine[-1]["rays_per_sample"],
                     "frame_rate": round(panel[early]["frame_rate"], 2),
                     "window_samples_per_cpu_second": round(panel[early]["samples_per_cpu_second"]),
                     "noise": panel[early]["noise"], "noise_spp": early,
                     "noise_late": panel[late]["noise"], "noise_late_spp": late,
                     "efficiency": float(f"{window_cpu_efficiency(panel[early], pixels):.4g}"),
                     "efficiency_wall": panel[early]["efficiency"],
                     "relative_rmse_longest": mine[-1]["relative_rmse"],
                     "cpu_seconds_longest": mine[-1]["cpu_seconds"],
                     "seconds_longest": mine[-1]["seconds"]})
    return rows


def fmt(x, digits=3):
    """A number for a table: DIGITS significant digits, millions as "M"."""
    if x == 0:
        return "0"
    if abs(x) >= 1e5:
        return fmt(x / 1e6, digits) + " M"
    return f"{x:.{max(digits - 1 - math.floor(math.log10(abs(x))), 0)}f}"


def load_words(load):
    """How busy the machine was in the run, in words, from run.json's "cpu_time"."""
    if not load or not load.get("renders"):
        return ""
    share = load.get("cpu_share") or {}
    busy = (f"{load['busy_renders']} of its {load['renders']} headless renders found the machine "
            "busy" if load["busy_renders"] else
            f"none of its {load['renders']} headless renders found the machine busy")
    return (f" In this run {busy}: their render threads had {100 * share['min']:.0f}% to "
            f"{100 * share['max']:.0f}% of their cores (median {100 * share['median']:.0f}%)."
            if share else f" In this run {busy}.")


def estimators_block(rows, p, threads, load=None):
    best = max(rows, key=lambda r: r["efficiency"])
    early, late = int(rows[0]["noise_spp"]), int(rows[0]["noise_late_spp"])
    size = p["window_size"]
    lines = [
        f"| estimator | samples per CPU-second (headless, {p['study_size']}², {threads} threads) "
        f"| rays per sample | frame rate ({size}² window, wall clock) | samples per CPU-second "
        f"(the same window) | noise after {early} frames | noise after {late} frames "
        f"| efficiency per CPU-second after {early} frames | the panel's efficiency (per second "
        f"of wall time) after {early} frames | relative RMSE of the longest render |",
        "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|"]
    for r in rows:
        lines.append(f"| {r['label']} | {fmt(r['samples_per_cpu_second'])} | {fmt(r['rays_per_sample'])} "
                     f"| {r['frame_rate']:.1f} fps | {fmt(r['window_samples_per_cpu_second'])} "
                     f"| {r['noise']:.3f} | {r['noise_late']:.3f} | {fmt(r['efficiency'])} "
                     f"| {fmt(r['efficiency_wall'])} "
                     f"| {fmt(r['relative_rmse_longest'])} in {r['cpu_seconds_longest']:.1f} CPU-s |")
    apart = max(abs(r["window_samples_per_cpu_second"] / r["samples_per_cpu_second"] - 1)
                for r in rows)
    lines.append("")
    lines.append(f"Most efficient in this run, by efficiency per CPU-second: **{best['label']}**. "
                 f"The frame rate is the window's panel's at {size}×{size} under a virtual display, "
                 "wall-clock time: what you wait for, lowered by whatever else runs on the machine "
                 "(here also the display's software drawing). The samples per CPU-second count the "
                 "render threads' CPU time alone, which other programs change little, so they are "
                 "about the same in the window and headless (`--stats`; here within "
                 f"{math.ceil(100 * apart)}%): compare yours with these. The efficiency per "
                 "CPU-second is 1/(noise² × CPU seconds), the window's CPU seconds being frames × "
                 f"{size}² ÷ samples per CPU-second; the panel's own efficiency counts wall-clock "
                 f"seconds instead: up to {threads} times higher with {threads} render threads that "
                 "each have a core to themselves, less on a busy machine." + load_words(load) +
                 " Labs 1–3 converge to the depth-limited image, lab 4 to the unbiased one.")
    return "\n".join(lines)


def sweep_block(rows):
    best = max(rows, key=lambda r: r["efficiency"])
    lines = ["| continueProb | samples per CPU-second | rays per sample | noise of one sample (noise × √spp) | spp | relative RMSE at equal CPU time | efficiency 1/(relative MSE · CPU s) |",
             "|--:|--:|--:|--:|--:|--:|--:|"]
    for r in rows:
        lines.append(f"| {r['continue_prob']:g} | {fmt(r['samples_per_cpu_second'])} | {fmt(r['rays_per_sample'])} "
                     f"| {fmt(r['noise_per_sample'])} | {r['spp']:g} | {fmt(r['relative_rmse'])} | {fmt(r['efficiency'])} |")
    lines.append("")
    lines.append(f"Most efficient continueProb in this run: **{best['continue_prob']:g}**.")
    return "\n".join(lines)


def equal_time_block(images, p, threads):
    parts = [f"{images[e.key]['label']}: {images[e.key]['spp']} spp in "
             f"{images[e.key]['cpu_seconds']:.1f} CPU-s ({images[e.key]['seconds']:.1f} s)"
             for e in ESTIMATORS]
    budget = p["image_budget_cpu_seconds"]
    return (f"Each render: {p['image_size']}×{p['image_size']} pixels, about {budget:g} CPU-seconds "
            f"of rendering, summed over {threads} render threads (about {budget / threads:g} s of "
            f"wall time on an idle machine; in brackets, the wall time it took). "
            + "; ".join(parts) + ".")


def bias_block(bias):
    return (f"The depth limit's bias, the relative RMSE between the depth-limited and the unbiased "
            f"image, is {fmt(bias)} on this scene (the grey line in the plot).")


def read_csv(path):
    """Rows of a CSV written by write_csv, numbers as floats."""
    def value(text):
        try:
            return float(text)
        except ValueError:
            return text
    with open(path, newline="") as f:
        return [{k: value(v) for k, v in row.items()} for row in csv.DictReader(f)]


def generated_blocks(figures):
    """The handouts' generated blocks, {name: text}, from the numbers in FIGURES (so they can be
    redone without rendering, --blocks-only, and checked against the handouts: ctest handouts)."""
    with open(os.path.join(figures, "run.json")) as f:
        run = json.load(f)
    with open(os.path.join(figures, "equal_time.json")) as f:
        images = json.load(f)
    with open(os.path.join(figures, "references.json")) as f:
        reference = json.load(f)["depth_limited"]
    bias, threads, p = reference["depth_limit_bias_relative_rmse"], reference["threads"], run["parameters"]
    return {"estimators-table": estimators_block(read_csv(os.path.join(figures, "estimators.csv")), p, threads,
                                                 run.get("cpu_time")),
            "sweep-table": sweep_block(read_csv(os.path.join(figures, "roulette_sweep.csv"))),
            "equal-time": equal_time_block(images, p, threads),
            "depth-limit-bias": bias_block(bias)}


def write_blocks(figures):
    """The handouts' tables, from the numbers in FIGURES."""
    update_blocks(generated_blocks(figures))


BLOCK = re.compile(r"(<!-- BEGIN generated: ([\w-]+) -->\n).*?(<!-- END generated: \2 -->)", re.S)


def update_blocks(blocks):
    """Replaces every generated block of handouts/*.md whose name is in BLOCKS."""
    found = set()
    for name in sorted(os.listdir(HANDOUTS)):
        if not name.endswith(".md"):
            continue
        path = os.path.join(HANDOUTS, name)
        with open(path) as f:
            text = f.read()

        def replace(m):
            if m.group(2) not in blocks:
                return m.group(0)
            found.add(m.group(2))
            return m.group(1) + blocks[m.group(2)] + "\n" + m.group(3)

        updated = BLOCK.sub(replace, text)
        if updated != text:
            with open(path, "w") as f:
                f.write(updated)
    for name in sorted(set(blocks) - found):
        print(f"make_figures: no handout has the generated block {name!r}", file=sys.stderr)


def load_summary(viewer):
    """What the renders' --stats said of the machine's load: how many found it busy, the render
    threads' share of their cores (of renders of half a second or more, as --stats' busy_note:
    a shorter one is mostly its threads starting), and the notes on CPU figures not to be
    trusted."""
    record = [r for r in viewer.cpu_record if r["name"] != "probe"]
    shares = sorted(r["cpu_share"] for r in record if r["cpu_share"] > 0 and r["seconds"] >= 0.5)
    return {"renders": len(record),
            "busy_renders": sum(1 for r in record if r["busy_note"]),
            "cpu_share": {"min": round(shares[0], 3), "median": round(statistics.median(shares), 3),
                          "max": round(shares[-1], 3)} if shares else {},
            "cpu_notes": sorted({r["cpu_note"] for r in record if r["cpu_note"]})}


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", help="the build folder holding viewer")
    parser.add_argument("--quick", action="store_true",
                        help="tiny renders into BUILD/handouts-quick, handouts left as they are")
    parser.add_argument("--blocks-only", action="store_true",
                        help="render nothing: rewrite the handouts' tables from handouts/figures/")
    parser.add_argument("--only-depth-sweep", action="store_true",
                        help="remake depth_sweep.csv alone")
    args = parser.parse_args()
    figures = os.path.join(HANDOUTS, "figures")
    if args.blocks_only:
        write_blocks(figures)
        return
    if not args.build:
        parser.error("--build is needed to render")
    build = os.path.abspath(args.build)
    p = QUICK if args.quick else FULL
    if args.quick:
        figures = os.path.join(build, "handouts-quick")
    os.makedirs(figures, exist_ok=True)
    if not shutil.which("gnuplot"):
        raise SystemExit("make_figures: gnuplot is needed (scripts/install-deps.sh installs it)")
    viewer = Viewer(os.path.join(build, "viewer"), SCENE, os.path.join(build, "handouts-renders"))
    if args.only_depth_sweep:
        write_csv(os.path.join(figures, "depth_sweep.csv"), depth_sweep(viewer, p))
        print(f"make_figures: {os.path.join(figures, 'depth_sweep.csv')}")
        return
    started = time.time()
    if os.getloadavg()[0] > 0.5:
        print(f"make_figures: the machine is busy (load average {os.getloadavg()[0]:.1f}); "
              "the figures by CPU time change little with that, the wall-clock ones (the "
              "window's frame rates, samples/s) will be low and noisy", file=sys.stderr)
    run = {"cpu": cpu_model(), "cores": os.cpu_count(), "load_average_at_start": os.getloadavg(),
           "parameters": p, "reference_continue_prob": REFERENCE_Q}

    references = make_references(viewer, p)
    convergence = convergence_study(viewer, p, references)
    sweep = roulette_sweep(viewer, p, references)
    depths = depth_sweep(viewer, p)
    window = window_table(viewer, p)
    images = equal_time_images(viewer, p, figures)

    bias = depth_limit_bias(references)
    write_csv(os.path.join(figures, "convergence.csv"), convergence)
    write_csv(os.path.join(figures, "roulette_sweep.csv"), sweep)
    write_csv(os.path.join(figures, "depth_sweep.csv"), depths)
    write_csv(os.path.join(figures, "estimators.csv"), estimator_rows(convergence, window, p))
    write_json(os.path.join(figures, "equal_time.json"), images)
    write_json(os.path.join(figures, "references.json"), {
        kind: {k: v for k, v in r.items() if k not in ("pixels", "image")} | {"depth_limit_bias_relative_rmse": bias}
        for kind, r in references.items()})
    gnuplot("convergence.gp", figures, data="convergence.csv", out="convergence.png", bias=bias,
            guide=slope_guide(convergence), threads=references["depth_limited"]["threads"])
    gnuplot("roulette_sweep.gp", figures, data="roulette_sweep.csv", out="roulette_sweep.png",
            budget=p["sweep_budget_cpu_seconds"])

    run["load_average_at_end"] = os.getloadavg()
    run["seconds"] = round(time.time() - started, 1)
    run["cpu_time"] = load_summary(viewer)
    write_json(os.path.join(figures, "run.json"), run)
    load = run["cpu_time"]
    if load["busy_renders"]:
        print(f"make_figures: {load['busy_renders']} of {load['renders']} renders found the machine "
              f"busy (the render threads had {100 * load['cpu_share']['min']:.0f}% to "
              f"{100 * load['cpu_share']['max']:.0f}% of their cores): the figures by CPU time "
              "hold, the wall-clock ones (seconds, samples/s, the window's frame rates) do not")
    for note in load["cpu_notes"]:
        print(f"make_figures: {note}")
    if not args.quick:
        write_blocks(figures)
    print(f"make_figures: figures in {figures} ({run['seconds']:.0f} s)")


if __name__ == "__main__":
    main()
