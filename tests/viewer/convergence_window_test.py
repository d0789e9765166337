#!/usr/bin/env python3
"""The window's convergence plot under a virtual X server (Xvfb), captured with --capture-window.

Usage: convergence_window_test.py VIEWER MODELS_DIR. Each check prints PASS/FAIL; the script
exits non-zero if any failed. Fixed seeds throughout.

- With --reference of the window's size: a run of lab 3, then (key 2, sent with xdotool) one of
  lab 2, which restarts accumulation; the capture after the last frame shows the Convergence
  section in the bottom right corner with both runs' curves and legend lines, each in its own
  colour (apps/viewer/convergence_plot.cpp: runColour), the first run kept beside the second.
- Without a reference of the window's size (none given, none cached in build/references/ for
  this size), there are no curves: the section is folded into its title bar in the top right
  corner, and says how to make one when unfolded.
The capture is kept as convergence-window.png in the tests' folder, to be looked at.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))
from checks import check, exit_code  # noqa: E402
from png_pixels import read_png  # noqa: E402
from window_display import virtual_display_env  # noqa: E402

VIEWER, MODELS = sys.argv[1], sys.argv[2]
SCENE = os.path.join(MODELS, "cornell_box_VI2_Specular.ecs")
WIDTH, HEIGHT = 640, 480
COMMON = ["-c", SCENE, "--size", str(WIDTH), str(HEIGHT), "--solution", "--seed", "5"]
# The first two runs' colours (convergence_plot.cpp: runColour).
RUN_COLOURS = [(27, 200, 150), (255, 127, 14)]


def near(rgb, colour, tolerance=10):
    return all(abs(a - b) <= tolerance for a, b in zip(rgb, colour))


def colour_counts(path):
    """Pixels of each run's colour in the capture's bottom right quadrant, where the section is."""
    width, height, rows = read_png(path)
    corner = [rgb for row in rows[height // 3:] for rgb in row[width // 3:]]
    return [sum(1 for rgb in corner if near(rgb, c)) for c in RUN_COLOURS]


def two_runs_on_one_plot(env, tmp):
    reference = os.path.join(tmp, "reference.exr")
    subprocess.run([VIEWER, *COMMON, "--lab", "importance", "--spp", "8", "--seed", "11", "-o",
                    reference], check=True, capture_output=True, timeout=300)
    shot = os.path.join(tmp, "with-reference.png")
    process = subprocess.Popen([VIEWER, *COMMON, "--lab", "importance", "--reference", reference,
                                "--frames", "10", "--print-frame-rate", "--capture-window", shot],
                               env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               text=True, bufsize=1)
    deadline, seen = time.time() + 120, False
    while time.time() < deadline:
        line = process.stdout.readline()
        if not line:
            break
        if re.match(r"^frame 5:", line):
            seen = True
            break
    check(seen, "the window renders lab 3 against the reference")
    window = subprocess.run(["xdotool", "search", "--sync", "--onlyvisible", "--pid",
                             str(process.pid)], env=env, capture_output=True, text=True,
                            timeout=30).stdout.split()
    if window:
        subprocess.run(["xdotool", "windowfocus", "--sync", window[0]], env=env, timeout=10)
        subprocess.run(["xdotool", "key", "2"], env=env, timeout=10)
    check(bool(window), "xdotool finds the window and sends key 2 (lab 2)")
    output, _ = process.communicate(timeout=300)
    check(process.returncode == 0 and "lab uniform" in output,
          f"the window goes on with lab 2 and ends after its 10 frames: exit "
          f"{process.returncode}")
    if not os.path.exists(shot):
        check(False, "the window was captured")
        return
    shutil.copy(shot, os.path.join(os.getcwd(), "convergence-window.png"))
    first, second = colour_counts(shot)
    check(first >= 30 and second >= 30,
          f"the section shows lab 3's run and lab 2's, each in its colour ({first} and {second} "
          f"pixels in the bottom right quadrant)")


def no_reference_no_curves(env, tmp):
    shot = os.path.join(tmp, "without-reference.png")
    run = subprocess.run([VIEWER, *COMMON[:2], "--size", "600", "450", "--lab", "importance",
                          "--solution", "--frames", "3", "--capture-window", shot], env=env,
                         capture_output=True, text=True, timeout=300)
    check(run.returncode == 0 and os.path.exists(shot),
          f"a window of a size with no reference runs: exit {run.returncode} ({run.stderr.strip()})")
    if os.path.exists(shot):
        first, second = colour_counts(shot)
        check(first < 5 and second < 5, f"and plots nothing ({first}, {second} run pixels)")


def main():
    with virtual_display_env() as env:
        with tempfile.TemporaryDirectory() as tmp:
            two_runs_on_one_plot(env, tmp)
            no_reference_no_curves(env, tmp)
    sys.exit(exit_code())


if __name__ == "__main__":
    main()
