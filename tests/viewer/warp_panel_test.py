#!/usr/bin/env python3
"""The warp test in the window, ctest `viewer.warp_panel`.

Usage: warp_panel_test.py VIEWER MODELS_DIR. Starts its own Xvfb; each check prints PASS/FAIL and
the script exits non-zero if any failed.

--warp-panel opens the window with the lab's warp test shown: the capture holds the panel's
cells in the heat palette's colours, where the same capture without it has far fewer, and the
verdict is printed ("warp test: ... passed" for the reference solution of lab 5). The t key runs
it in a running window; for a lab that writes no lobe it says so instead of failing.
"""
import os
import queue
import subprocess
import sys
import tempfile
import threading

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import check, exit_code  # noqa: E402
from png_pixels import read_png  # noqa: E402
from window_display import virtual_display_env  # noqa: E402

VIEWER, MODELS = sys.argv[1], sys.argv[2]
SCENE = os.path.join(MODELS, "veach_plates.ecs")
# Stops of the heat palette the counts are drawn in (pathlab/images/false_colour.h): its reds,
# yellows and greens, which veach_plates' greys and the panels' text do not have.
HEAT = [(255, 0, 0), (255, 255, 0), (0, 255, 0)]


def heat_pixels(path):
    _, _, image = read_png(path)
    return sum(1 for row in image for rgb in row
               if any(all(abs(a - b) <= 40 for a, b in zip(rgb, c)) for c in HEAT))


def panel_in_capture(env, tmp):
    common = ["-c", SCENE, "--size", "640", "480", "--lab", "glossy", "--solution",
              "--frames", "2"]
    counts, outputs = {}, {}
    for name, extra in (("plain", []), ("panel", ["--warp-panel"])):
        shot = os.path.join(tmp, f"{name}.png")
        run = subprocess.run([VIEWER, *common, *extra, "--capture-window", shot], env=env,
                             capture_output=True, text=True, timeout=120)
        check(run.returncode == 0 and os.path.exists(shot),
              f"{' '.join(extra) or 'without --warp-panel'}: exit {run.returncode} "
              f"({run.stderr.strip()[-300:]})")
        outputs[name] = run.stdout
        counts[name] = heat_pixels(shot) if os.path.exists(shot) else 0
    check("warp test: " in outputs["panel"] and "passed: sampleLobe and lobePdf of lab glossy" in
          outputs["panel"],
          f"--warp-panel prints the reference solution's verdict: {outputs['panel'].strip()[-300:]!r}")
    check(counts["panel"] - counts["plain"] >= 500,
          f"the capture shows the panel's cells: {counts['panel']} pixels of the heat palette "
          f"against {counts['plain']} without --warp-panel")


def lab_without_lobe(env, tmp):
    shot = os.path.join(tmp, "roulette.png")
    run = subprocess.run([VIEWER, "-c", SCENE, "--size", "320", "240", "--lab", "roulette",
                          "--solution", "--frames", "2", "--warp-panel", "--capture-window", shot],
                         env=env, capture_output=True, text=True, timeout=120)
    check(run.returncode == 0 and "writes no lobe to test" in run.stdout,
          f"a lab without a lobe: the panel says so and the window runs on (exit {run.returncode}, "
          f"{run.stdout.strip()[-200:]!r})")


def key_runs_it(env):
    process = subprocess.Popen([VIEWER, "-c", SCENE, "--size", "320", "240", "--lab", "glossy",
                                "--solution"], env=env, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True, bufsize=1)
    lines = queue.Queue()

    def read():
        for line in process.stdout:
            lines.put(line)
        lines.put(None)

    threading.Thread(target=read, daemon=True).start()
    try:
        found = subprocess.run(["xdotool", "search", "--sync", "--onlyvisible", "--pid",
                                str(process.pid)], env=env, capture_output=True, text=True,
                               timeout=30).stdout.split()
        check(bool(found), "xdotool finds the window")
        if not found:
            return
        subprocess.run(["xdotool", "key", "--window", found[0], "t"], env=env, timeout=10)
        said = ""
        while "warp test: " not in said:
            try:
                line = lines.get(timeout=60)
            except queue.Empty:
                break
            if line is None:
                break
            said += line
        check("warp test: " in said and "passed" in said,
              f"the t key runs the warp test of the window's lab: {said.strip()[-200:]!r}")
    finally:
        process.kill()
        process.wait()


def main():
    with virtual_display_env() as env, tempfile.TemporaryDirectory() as tmp:
        panel_in_capture(env, tmp)
        lab_without_lobe(env, tmp)
        key_runs_it(env)
    sys.exit(exit_code())


if __name__ == "__main__":
    main()
