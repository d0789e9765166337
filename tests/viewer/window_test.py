#!/usr/bin/env python3
"""The viewer's window under a virtual X server (Xvfb), driven by simulated keys (xdotool).

Usage: window_test.py VIEWER MODELS_DIR STUCK_VIEWER. STUCK_VIEWER is a viewer whose lab 2 never
returns (the grader's mutant uniform_endless_loop). Starts its own Xvfb; each check prints
PASS/FAIL and the script exits non-zero if any failed.

A window whose lab is stuck in an endless loop ends, with a short --watchdog, with exit status 1
and the line naming the lab's file, rather than hang, and its close with it.

Statistical check: the screenshot's mean radiance against a headless render of the same scene,
spp and seed, per channel, z-test at alpha = 1e-4 (|z| < 3.89) with the headless render's
standard error. (The two are in fact bit-identical: the same sample streams.)

The figures a student writes down are one measurement wherever they are read: after N frames the
panel's noise and efficiency (--print-frame-rate prints the panel's figures), the window's --stats
and a headless render of N spp give the same noise, and the frame rate printed is the median the
panel shows, labelled as such.
"""
import json
import os
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import check, exit_code  # noqa: E402
from window_display import virtual_display_env  # noqa: E402

VIEWER, MODELS, STUCK_VIEWER = sys.argv[1], sys.argv[2], sys.argv[3]
SCENE = os.path.join(MODELS, "cornell_box_VI2_Specular.ecs")



def image_means(path):
    """Per-channel averages of an image, from OpenImageIO's oiiotool."""
    out = subprocess.run(["oiiotool", path, "--printstats"], capture_output=True, text=True).stdout
    line = next(l for l in out.splitlines() if "Stats Avg" in l)
    return [float(x) for x in re.findall(r"[-\d.e+]+", line.split(":")[1])[:3]]


def screenshot_matches_headless(env, tmp):
    shot = os.path.join(tmp, "window.exr")
    common = ["-c", SCENE, "--size", "96", "72", "--lab", "importance", "--solution", "--seed", "4"]
    run = subprocess.run([VIEWER, *common, "--frames", "6", "--screenshot", shot],
                         env=env, capture_output=True, text=True, timeout=120)
    check(run.returncode == 0, f"--frames 6 --screenshot exits 0 ({run.stderr.strip()})")
    check(os.path.exists(shot), "the screenshot was written")
    if not os.path.exists(shot):
        return
    window = image_means(shot)
    check(sum(window) / 3 > 0.01, f"the screenshot is not black (mean {window})")
    stats = os.path.join(tmp, "headless.json")
    subprocess.run([VIEWER, *common, "--spp", "6", "-o", os.path.join(tmp, "headless.exr"),
                    "--stats", stats], check=True, capture_output=True)
    s = json.load(open(stats))
    n = s["width"] * s["height"] * s["spp"]
    for c in range(3):
        se = max((s["mean_variance"][c] / n) ** 0.5, 1e-9)
        z = (window[c] - s["mean_radiance"][c]) / se
        check(abs(z) < 3.89, f"channel {c}: window {window[c]:.5f} vs headless "
                             f"{s['mean_radiance'][c]:.5f}, z = {z:.2f}")


FRAME_LINE = re.compile(r"^frame (\d+): median ([\d.]+) fps \(([\d.]+) ms\) over the last (\d+) frames, "
                        r"this frame ([\d.]+) fps; (\d+) spp, .* noise ([\d.]+), efficiency ")


def panel_stats_and_headless_agree(env, tmp):
    common = ["-c", SCENE, "--size", "96", "72", "--lab", "uniform", "--solution", "--seed", "8"]
    window_stats = os.path.join(tmp, "window.json")
    run = subprocess.run([VIEWER, *common, "--frames", "40", "--print-frame-rate", "--stats",
                          window_stats, "--screenshot", os.path.join(tmp, "w.pfm")],
                         env=env, capture_output=True, text=True, timeout=120)
    lines = [FRAME_LINE.match(line) for line in run.stdout.splitlines()]
    lines = [m for m in lines if m]
    check(run.returncode == 0 and len(lines) == 40,
          f"--print-frame-rate prints one labelled line per frame ({len(lines)} of 40)")
    if not lines or not os.path.exists(window_stats):
        return
    last = lines[-1]
    check(int(last.group(4)) == 31 and abs(1000 / float(last.group(2)) - float(last.group(3))) < 0.2,
          f"the printed frame rate is the median of the last 31 frames: {last.group(0)}")
    w = json.load(open(window_stats))
    check(abs(w["frames_per_second"] - float(last.group(2))) < 0.01 and
          "median" in w["frames_per_second_source"],
          f"the window's --stats holds the panel's median frame rate, labelled: "
          f"{w['frames_per_second']:.2f} ({w['frames_per_second_source']})")
    headless_stats = os.path.join(tmp, "headless40.json")
    subprocess.run([VIEWER, *common, "--spp", "40", "-o", os.path.join(tmp, "h.pfm"), "--stats",
                    headless_stats], check=True, capture_output=True)
    h = json.load(open(headless_stats))
    panel = float(last.group(7))
    check(abs(panel - w["noise"]) < 1e-4 and abs(w["noise"] - h["noise"]) < 1e-9,
          f"after 40 frames the panel's noise {panel}, the window's --stats {w['noise']:.6f} and "
          f"a headless render of 40 spp {h['noise']:.6f} agree")
    check("samples_per_second / (width x height)" in h["frames_per_second_source"] and
          abs(h["frames_per_second"] - h["samples_per_second"] / (96 * 72)) < 1e-6 * h["frames_per_second"],
          "a headless render's frame rate is samples/s / pixels, labelled as such")


class Viewer:
    """A viewer process whose --print-frame-rate lines can be awaited."""

    def __init__(self, env, args):
        self.process = subprocess.Popen([VIEWER, *args], env=env, stdout=subprocess.PIPE,
                                        stderr=subprocess.STDOUT, text=True, bufsize=1)
        self.lines = []

    def wait_for(self, pattern, timeout=60):
        deadline = time.time() + timeout
        while time.time() < deadline:
            line = self.process.stdout.readline()
            if not line:
                return None
            self.lines.append(line)
            if re.search(pattern, line):
                return line
        return None


def keys_change_what_the_viewer_reports(env):
    viewer = Viewer(env, ["-c", SCENE, "--size", "160", "120", "--print-frame-rate", "--solution"])
    first = viewer.wait_for(r"^frame \d+:")
    check(first is not None and "lab branching" in first, "the window renders frames")
    window = subprocess.run(["xdotool", "search", "--sync", "--onlyvisible", "--pid",
                             str(viewer.process.pid)], env=env, capture_output=True, text=True,
                            timeout=30).stdout.split()
    check(bool(window), "xdotool finds the window")
    if not window:
        viewer.process.kill()
        return
    xdo = ["xdotool"]

    def key(name):
        subprocess.run(xdo + ["windowfocus", "--sync", window[0]], env=env, timeout=10)
        subprocess.run(xdo + ["key", name], env=env, timeout=10)

    key("2")
    check(viewer.wait_for(r"lab uniform") is not None, "key 2 switches to the uniform lab")
    key("Tab")
    check(viewer.wait_for(r"impl student") is not None, "Tab switches to the student's code")
    key("bracketright")
    check(viewer.wait_for(r"max-depth 4") is not None, "] raises maxDepth")
    key("f")
    check(viewer.wait_for(r"size 800x600") is not None, "f makes the window fullscreen (800x600)")
    key("f")
    check(viewer.wait_for(r"size 160x120") is not None, "f again restores the window")
    key("q")
    try:
        code = viewer.process.wait(timeout=30)
    except subprocess.TimeoutExpired:
        viewer.process.kill()
        code = None
    check(code == 0, f"q quits cleanly (exit status {code})")


def stuck_window_ends(env):
    start = time.time()
    try:
        run = subprocess.run([STUCK_VIEWER, "-c", SCENE, "--size", "64", "48", "--lab", "uniform",
                              "--watchdog", "2", "--frames", "2"], env=env, capture_output=True,
                             text=True, timeout=60)
    except subprocess.TimeoutExpired:
        check(False, "a window whose lab never returns ends within 60 s (it ran on)")
        return
    stuck = [line for line in run.stderr.splitlines()
             if "an endless loop, or recursion that never ends?" in line]
    check(run.returncode == 1 and time.time() - start < 30 and len(stuck) == 1 and
          "labs/uniform.cpp" in stuck[0],
          f"a window whose lab never returns ends with --watchdog 2: exit status "
          f"{run.returncode} after {time.time() - start:.1f} s, saying {run.stderr.strip()!r}")


def no_display_is_explained():
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    run = subprocess.run([VIEWER, "-c", SCENE], env=env, capture_output=True, text=True, timeout=30)
    check(run.returncode == 2, f"without a display the viewer exits 2 (got {run.returncode})")
    check("no display" in run.stderr and "-o" in run.stderr and run.stderr.count("\n") == 1,
          f"and says so in one line pointing to -o: {run.stderr.strip()!r}")


def main():
    no_display_is_explained()
    with virtual_display_env() as env:
        with tempfile.TemporaryDirectory() as tmp:
            screenshot_matches_headless(env, tmp)
            panel_stats_and_headless_agree(env, tmp)
        keys_change_what_the_viewer_reports(env)
        stuck_window_ends(env)
    sys.exit(exit_code())


if __name__ == "__main__":
    main()
