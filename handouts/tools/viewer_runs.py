"""Runs PathLab's viewer for the figures: headless renders, and the window under Xvfb."""
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from virtual_display import start_xvfb  # noqa: E402,F401  (make_figures imports it from here)


class Viewer:
    """One build's viewer and a folder for what it renders."""

    def __init__(self, executable, scene, work):
        self.executable = executable
        self.scene = scene
        self.work = work
        os.makedirs(work, exist_ok=True)

    def estimator_options(self, lab, continue_prob=None, max_depth=None):
        options = ["-c", self.scene, "--lab", lab, "--solution"]
        if continue_prob is not None:
            options += ["--continue-prob", f"{continue_prob:g}"]
        if max_depth is not None:
            options += ["--max-depth", str(max_depth)]
        return options

    def render(self, name, lab, spp, size, seed, continue_prob=None, max_depth=None,
               extension="pfm"):
        """Renders headless into WORK/NAME.EXTENSION; returns the stats JSON as a dict, with
        "image" set to the image's path."""
        image = os.path.join(self.work, f"{name}.{extension}")
        stats = os.path.join(self.work, f"{name}.json")
        command = [self.executable, *self.estimator_options(lab, continue_prob, max_depth),
                   "--spp", str(spp), "--size", str(size), str(size), "--seed", str(seed),
                   "-o", image, "--stats", stats]
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        with open(stats) as f:
            result = json.load(f)
        result["image"] = image
        return result

    def samples_per_second(self, lab, size, continue_prob=None, seed=777, at_least_seconds=0.4):
        """Throughput of a solution at SIZE², from renders doubled in spp until one lasts
        AT_LEAST_SECONDS (a short render mostly measures start-up noise)."""
        spp = 1
        while True:
            stats = self.render("probe", lab, spp, size, seed, continue_prob)
            if stats["seconds"] >= at_least_seconds or spp >= 4096:
                return stats["samples_per_second"]
            spp *= 2


FRAME_LINE = re.compile(r"frame (\d+): median ([\d.]+) fps .* (\d+) spp, .* noise ([\d.]+), "
                        r"efficiency ([\d.e+-]+);")


def window_measurement(viewer, display, lab, size, frames, continue_prob=None):
    """What a student reads off the window's panel (one sample per pixel per frame): after each
    of FRAMES, {"frame_rate": the panel's median frame rate, "noise", "efficiency", "spp"}."""
    with tempfile.TemporaryDirectory() as tmp:
        run = subprocess.run(
            [viewer.executable, *viewer.estimator_options(lab, continue_prob), "--size",
             str(size), str(size), "--print-frame-rate", "--frames", str(max(frames)),
             "--screenshot", os.path.join(tmp, "window.exr")],
            env=dict(os.environ, DISPLAY=display), capture_output=True, text=True, check=True,
            timeout=1200)
    panel = {}
    for line in run.stdout.splitlines():
        m = FRAME_LINE.search(line)
        if m and int(m.group(1)) in frames:
            panel[int(m.group(1))] = {"frame_rate": float(m.group(2)), "spp": int(m.group(3)),
                                      "noise": float(m.group(4)), "efficiency": float(m.group(5))}
    missing = sorted(set(frames) - set(panel))
    if missing:
        raise RuntimeError(f"the window printed no line for frames {missing}")
    return panel
