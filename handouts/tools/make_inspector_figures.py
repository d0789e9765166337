#!/usr/bin/env python3
"""Makes the handouts' path-inspector screenshots: the window with one pixel inspected.

Usage: make_inspector_figures.py --build BUILD [--out FOLDER]

For each lab, its reference solution in the window on the VI2 Cornell box at 512x512 (under a
virtual X server, Xvfb), opened with
`viewer --inspect X Y --inspect-window` and captured with --capture-window once the replay is in:
the pixel's 8 samples drawn over the image (segments coloured by the kind of ray, shadow rays
dashed) and the inspector's panel with sample 0's table. Writes handouts/figures/inspector_LAB.png
(or into --out). The pixel is on the left red wall, whence paths cross the box to the mirror
block, the glass sphere and the light: of a few such pixels, the one whose sample 0 has the most
vertices (headless `--inspect-out`), so that lab 1's branches, labs 2 and 3's one pick per vertex
and lab 4's roulette (at continueProb 0.8, as graded, so that paths go on) show. The images
depend only on the seed; the replay runs on a thread of its own, and the capture waits for it.

Python 3 standard library and Xvfb only; a few seconds per lab.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

TOOLS = os.path.dirname(os.path.abspath(__file__))
HANDOUTS = os.path.dirname(TOOLS)
SOURCE = os.path.dirname(HANDOUTS)
SCENE = os.path.join(SOURCE, "models", "cornell_box_VI2_Specular.ecs")

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
from virtual_display import start_xvfb  # noqa: E402

SIZE = 512
# Pixels on the left red wall, below the figures' panel and above the inspector's.
CANDIDATES = [(x, y) for y in (192, 218, 243, 256, 269) for x in (20, 30, 45, 58)]
# (lab, options) of each lab's figure.
FIGURES = [
    ("branching", []),
    ("uniform", []),
    ("importance", []),
    ("roulette", ["--continue-prob", "0.8"]),
]


def common(lab, options):
    return ["-c", SCENE, "--size", str(SIZE), str(SIZE), "--lab", lab, "--solution", "--seed",
            "0", *options]


def sample_zero_vertices(viewer, lab, options, pixel, work):
    out = os.path.join(work, "inspection.json")
    subprocess.run([viewer, *common(lab, options), "--inspect", str(pixel[0]), str(pixel[1]),
                    "--inspect-samples", "1", "--inspect-out", out], check=True,
                   capture_output=True)
    with open(out) as f:
        return len(json.load(f)["samples"][0]["vertices"])


def best_pixel(viewer, lab, options):
    """The candidate whose sample 0 has the most vertices (the first of equals)."""
    with tempfile.TemporaryDirectory() as work:
        counts = [sample_zero_vertices(viewer, lab, options, p, work) for p in CANDIDATES]
    return CANDIDATES[counts.index(max(counts))]


def capture(viewer, display, lab, pixel, options, path):
    run = subprocess.run(
        [viewer, *common(lab, options), "--inspect", str(pixel[0]), str(pixel[1]),
         "--inspect-window", "--frames", "32", "--capture-window", path],
        env=dict(os.environ, DISPLAY=display), capture_output=True, text=True, timeout=300)
    if run.returncode != 0:
        raise SystemExit(f"make_inspector_figures: {lab}: {run.stderr.strip()}")
    print(f"wrote {os.path.relpath(path, SOURCE)}: lab {lab}, pixel {pixel}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", required=True, help="the build folder, with viewer")
    parser.add_argument("--out", default=os.path.join(HANDOUTS, "figures"))
    args = parser.parse_args()
    if not shutil.which("Xvfb"):
        raise SystemExit("make_inspector_figures: Xvfb is needed (apt-get install xvfb)")
    viewer = os.path.join(args.build, "viewer")
    os.makedirs(args.out, exist_ok=True)
    server, display = start_xvfb("1024x768x24")
    try:
        for lab, options in FIGURES:
            capture(viewer, display, lab, best_pixel(viewer, lab, options), options,
                    os.path.join(args.out, f"inspector_{lab}.png"))
    finally:
        server.terminate()
        server.wait()


if __name__ == "__main__":
    main()
