"""Runs PathLab's viewer for the figures: headless renders, and the window under Xvfb."""
import json
import os
import re
import statistics
import subprocess
import tempfile


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


def start_xvfb():
    """An X server on a free display number (which Xvfb reports on a pipe)."""
    read, write = os.pipe()
    server = subprocess.Popen(["Xvfb", "-displayfd", str(write), "-screen", "0", "1024x768x24",
                               "-nolisten", "tcp"], pass_fds=[write], stderr=subprocess.DEVNULL)
    os.close(write)
    number = b""
    while not number.endswith(b"\n"):
        chunk = os.read(read, 16)
        if not chunk:
            raise RuntimeError("Xvfb did not start")
        number += chunk
    os.close(read)
    return server, ":" + number.decode().strip()


FRAME_LINE = re.compile(r"frame (\d+): ([\d.]+) fps, .* (\d+) spp, .* noise ([\d.]+)")


def window_measurement(viewer, display, lab, size, frames, continue_prob=None):
    """What a student reads off the window's panel after FRAMES frames (one sample per pixel
    each): the median frame rate of the last 31 frames, as the panel shows it, and the noise
    figure (mean relative standard error of the pixel estimates)."""
    with tempfile.TemporaryDirectory() as tmp:
        run = subprocess.run(
            [viewer.executable, *viewer.estimator_options(lab, continue_prob), "--size",
             str(size), str(size), "--print-frame-rate", "--frames", str(frames),
             "--screenshot", os.path.join(tmp, "window.exr")],
            env=dict(os.environ, DISPLAY=display), capture_output=True, text=True, check=True,
            timeout=600)
    lines = [FRAME_LINE.search(line) for line in run.stdout.splitlines()]
    lines = [m for m in lines if m]
    if len(lines) < frames:
        raise RuntimeError(f"the window printed {len(lines)} frame lines, expected {frames}")
    frame_rates = [float(m.group(2)) for m in lines[-31:]]
    return {"frame_rate": statistics.median(frame_rates), "noise": float(lines[-1].group(4)),
            "spp": int(lines[-1].group(3))}
