#!/usr/bin/env python3
"""The path inspector in the window, under a virtual X server (Xvfb), clicked with xdotool.

Usage: inspector_test.py VIEWER MODELS_DIR. Starts its own Xvfb; each check prints PASS/FAIL and
the script exits non-zero if any failed.

A click without motion and a shift+click inspect the pixel under the cursor (the window prints
"inspected pixel (X, Y)" when the replay is in); a drag orbits the camera and inspects nothing.
--inspect X Y --inspect-window opens the window with the pixel inspected: its capture shows the
paths in the overlay's colours over the image, where the same capture without it has none;
--inspect without --inspect-window stays headless (the table on stdout) even with a display.
"""
import os
import queue
import re
import subprocess
import sys
import tempfile
import threading

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import check, exit_code  # noqa: E402
from png_pixels import read_png  # noqa: E402
from window_display import virtual_display_env  # noqa: E402

VIEWER, MODELS = sys.argv[1], sys.argv[2]
SCENE = os.path.join(MODELS, "cornell_box_VI2_Specular.ecs")
INSPECTED = re.compile(r"^inspected pixel \((\d+), (\d+)\): (\d+) sample\(s\), lab (\w+) \((\w+)\)")
# The overlay's diffuse and mirror segments (apps/viewer/path_overlay.cpp).
OVERLAY_COLOURS = [(255, 200, 0), (0, 200, 255)]


class Viewer:
    """A window whose stdout lines can be awaited."""

    def __init__(self, env, args):
        self.process = subprocess.Popen([VIEWER, *args], env=env, stdout=subprocess.PIPE,
                                        stderr=subprocess.STDOUT, text=True, bufsize=1)
        # Read on a thread of its own: a window that prints nothing must not block the test.
        self.lines = queue.Queue()
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        for line in self.process.stdout:
            self.lines.put(line)
        self.lines.put(None)

    def wait_for(self, pattern, timeout=60):
        """The first match of `pattern` in the lines to come; none after `timeout` seconds."""
        while True:
            try:
                line = self.lines.get(timeout=timeout)
            except queue.Empty:
                return None
            if line is None:
                return None
            match = pattern.search(line)
            if match:
                return match

    def close(self):
        self.process.kill()
        self.process.wait()


def clicks_inspect(env):
    # Large enough for a band of image between the figures' panel (top left, about 150 pixels
    # high) and the inspector's (the lower 45 %, once a pixel is inspected).
    viewer = Viewer(env, ["-c", SCENE, "--size", "640", "480", "--solution", "--lab", "branching"])
    try:
        found = subprocess.run(["xdotool", "search", "--sync", "--onlyvisible", "--pid",
                                str(viewer.process.pid)], env=env, capture_output=True,
                               text=True, timeout=30).stdout.split()
        check(bool(found), "xdotool finds the window")
        if not found:
            return
        window = found[0]

        def xdo(*arguments):
            subprocess.run(["xdotool", *arguments], env=env, timeout=10)

        xdo("mousemove", "--window", window, "40", "200", "click", "1")
        match = viewer.wait_for(INSPECTED)
        check(match is not None and match.group(1, 2) == ("40", "200") and
              match.group(3) == "8" and match.group(4, 5) == ("branching", "solution"),
              f"a click on pixel (40, 200) inspects it, 8 samples of the window's lab: "
              f"{match.group(0) if match else 'nothing printed'}")
        # A drag orbits the camera and inspects nothing: the next line is the click after it.
        xdo("mousemove", "--window", window, "300", "200", "mousedown", "1")
        xdo("mousemove", "--window", window, "320", "210")
        xdo("mousemove", "--window", window, "340", "215", "mouseup", "1")
        xdo("keydown", "shift", "mousemove", "--window", window, "500", "190", "click", "1",
            "keyup", "shift")
        match = viewer.wait_for(INSPECTED)
        check(match is not None and match.group(1, 2) == ("500", "190"),
              f"a drag inspects nothing and a shift+click on (500, 190) inspects that pixel: "
              f"{match.group(0) if match else 'nothing printed'}")
    finally:
        viewer.close()


def overlay_pixels(path, rows):
    """Pixels of the overlay's colours in the given rows (between the panels)."""
    _, _, image = read_png(path)
    return sum(1 for row in image[rows[0]:rows[1]] for rgb in row
               if any(all(abs(a - b) <= 24 for a, b in zip(rgb, c)) for c in OVERLAY_COLOURS))


def inspect_window_draws_paths(env, tmp):
    common = ["-c", SCENE, "--size", "512", "512", "--lab", "branching", "--solution",
              "--frames", "2"]
    shots = {}
    for name, extra in (("plain", []), ("inspected", ["--inspect", "30", "256", "--inspect-window"])):
        shots[name] = os.path.join(tmp, f"{name}.png")
        run = subprocess.run([VIEWER, *common, *extra, "--capture-window", shots[name]], env=env,
                             capture_output=True, text=True, timeout=120)
        check(run.returncode == 0 and os.path.exists(shots[name]),
              f"{' '.join(extra) or 'without --inspect'}: exit {run.returncode} "
              f"({run.stderr.strip()})")
        if name == "inspected":
            check(INSPECTED.search(run.stdout) is not None,
                  f"--inspect-window prints the replay's line: {run.stdout.strip()!r}")
    if not all(os.path.exists(p) for p in shots.values()):
        return
    # Between the figures' panel (top left) and the inspector's (the lower 45 %).
    rows = (170, 270)
    plain, inspected = overlay_pixels(shots["plain"], rows), overlay_pixels(shots["inspected"], rows)
    check(inspected - plain >= 40,
          f"the capture shows the paths in the overlay's colours: {inspected} such pixels "
          f"against {plain} without --inspect-window")


def inspect_stays_headless_and_bad_input(env):
    run = subprocess.run([VIEWER, "-c", SCENE, "--size", "64", "64", "--solution", "--inspect",
                          "10", "30", "--inspect-samples", "2"], env=env, capture_output=True,
                         text=True, timeout=120)
    check(run.returncode == 0 and "arrived by" in run.stdout and "inspected pixel" not in run.stdout,
          f"--inspect without --inspect-window prints the table headless, display or not "
          f"(exit {run.returncode})")
    for extra, says in ((["--inspect-window"], "needs --inspect X Y"),
                        (["--inspect", "1", "1", "--inspect-window", "-o", "x.png"], "-o")):
        run = subprocess.run([VIEWER, "-c", SCENE, "--size", "64", "64", *extra], env=env,
                             capture_output=True, text=True, timeout=60)
        check(run.returncode == 2 and "--inspect-window" in run.stderr and says in run.stderr and
              run.stderr.count("\n") == 1,
              f"{' '.join(extra)}: exit 2 and one line ({run.returncode}, {run.stderr.strip()!r})")


def main():
    with virtual_display_env() as env:
        clicks_inspect(env)
        with tempfile.TemporaryDirectory() as tmp:
            inspect_window_draws_paths(env, tmp)
        inspect_stays_headless_and_bad_input(env)
    sys.exit(exit_code())


if __name__ == "__main__":
    main()
