"""Runs PathLab's viewer for the figures: headless renders, and the window under Xvfb."""
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import headless_viewer  # noqa: E402
from virtual_display import start_xvfb  # noqa: E402,F401  (make_figures imports it from here)


class Viewer:
    """One build's viewer and a folder for what it renders."""

    def __init__(self, executable, scene, work):
        self.executable = executable
        self.scene = scene
        self.work = work
        # Per render: its name, the render threads' share of their cores, and --stats' notes (a
        # busy machine, a CPU figure not to be trusted): what the figures' timings survived.
        self.cpu_record = []
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
        options = [*self.estimator_options(lab, continue_prob, max_depth), "--spp", str(spp),
                   "--size", str(size), str(size), "--seed", str(seed)]
        result = headless_viewer.render(self.executable, options, image, stats,
                                        f"the figure's render {name} failed")
        # The figures keep the viewer's --stats only: a wall time would change the committed
        # references.json at every run.
        result.pop("wall_seconds")
        result["image"] = image
        self.cpu_record.append({"name": name, "seconds": result["seconds"],
                                "cpu_share": result.get("cpu_share", 0),
                                "busy_note": result.get("busy_note", ""),
                                "cpu_note": result.get("cpu_note", "")})
        return result

    def samples_per_cpu_second(self, lab, size, continue_prob=None, seed=777,
                               at_least_cpu_seconds=0.8):
        """Samples per CPU-second of a solution at SIZE², the render threads' CPU time, which
        other programs on the machine change little: from renders doubled in spp until one takes
        AT_LEAST_CPU_SECONDS (a short render mostly measures its threads starting)."""
        spp = 1
        while True:
            stats = self.render("probe", lab, spp, size, seed, continue_prob)
            if stats["cpu_seconds"] >= at_least_cpu_seconds or spp >= 4096:
                return stats["samples_per_cpu_second"]
            spp *= 2


# The window's --print-frame-rate line (apps/viewer/frame_report.cpp): "frame N: median F fps
# ... ; S spp, R rays/s, C samples per CPU-second, noise Z, efficiency E; lab ...".
FRAME_LINE = re.compile(r"frame (\d+): median ([\d.]+) fps .* (\d+) spp, [^,]* rays/s, "
                        r"([\d.e+-]+) samples per CPU-second, noise ([\d.]+), "
                        r"efficiency ([\d.e+-]+);")


def window_measurement(viewer, display, lab, size, frames, continue_prob=None):
    """What a student reads off the window's panel (one sample per pixel per frame): after each
    of FRAMES, {"frame_rate": the panel's median frame rate (wall time, what a student waits
    for), "samples_per_cpu_second" (the render threads' CPU time since the start: the figure
    other programs change little), "noise", "efficiency" (the panel's: per second of wall time
    rendering), "spp"}."""
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
                                      "samples_per_cpu_second": float(m.group(4)),
                                      "noise": float(m.group(5)), "efficiency": float(m.group(6))}
    missing = sorted(set(frames) - set(panel))
    if missing:
        raise RuntimeError(f"the window printed no line for frames {missing}")
    return panel
