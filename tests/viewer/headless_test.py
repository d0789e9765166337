#!/usr/bin/env python3
"""viewer -o: what a student sees of a render that goes wrong, ctest viewer.headless.

Usage: headless_test.py VIEWER MUTANTS_DIR MODELS_DIR. MUTANTS_DIR holds viewers built around
the grader's mutant labs (tests/grader/mutants/NAME/, the other labs being the solutions), each
named after its mutant. Each check prints PASS/FAIL; the script exits non-zero if any failed.

- A lab caught in an endless loop (the mutant uniform_endless_loop) ends, with a short
  --watchdog, within a bounded time: exit status 1 and one line naming the lab's file and the
  likely cause; bad --watchdog values are refused with exit status 2.
- A lab whose recursion never ends (the mutant branching_no_depth_limit, in a closed furnace)
  overflows its stack at once: the process still ends by SIGSEGV, as the grader reads a crash,
  after one line naming the lab's file and the likely cause; a null pointer (branching_crash)
  is named alike.
- The watchdog changes nothing in the image: a correct lab renders the same bytes with it on
  (briefly and by default) as with it off.
- A lab that returns NaN (the mutant roulette_nan): the NaN warning comes before the render's
  figures, which give no noise or efficiency as if they meant something.
- On a terminal a render draws a progress line (bar, percentage, time left); in a pipe, nothing.
- The render threads' CPU time: per-thread clocks by default, samples per CPU-second agreeing
  with the samples and that time; where a platform has no per-thread clock (PATHLAB_CPU_CLOCK=
  process stands in for one), the process's clock, said in one line and in --stats.
"""
import json
import os
import pty
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import check, run_in_scratch_folder  # noqa: E402

VIEWER, MUTANTS, MODELS = sys.argv[1], sys.argv[2], sys.argv[3]
SCENE = os.path.join(MODELS, "cornell_box_VI2_Specular.ecs")
STUCK = "an endless loop, or recursion that never ends?"


def run_on_terminal(argv, timeout):
    """Runs argv with stdout and stderr on one pseudo-terminal, as in a student's terminal: both
    line-buffered or unbuffered, so the text comes in the order the program wrote it. Returns
    (exit status, the text)."""
    leader, follower = pty.openpty()
    process = subprocess.Popen(argv, stdout=follower, stderr=follower, stdin=subprocess.DEVNULL)
    os.close(follower)
    text = b""
    deadline = time.time() + timeout
    while time.time() < deadline:
        try:
            chunk = os.read(leader, 65536)
        except OSError:  # the terminal closed: the program ended
            break
        if not chunk:
            break
        text += chunk
    os.close(leader)
    try:
        code = process.wait(timeout=max(1, deadline - time.time()))
    except subprocess.TimeoutExpired:
        process.kill()
        code = None
    return code, text.decode(errors="replace")


def endless_loop_is_stopped(tmp):
    mutant = os.path.join(MUTANTS, "uniform_endless_loop")
    start = time.time()
    try:
        run = subprocess.run([mutant, "-c", SCENE, "--lab", "uniform", "--size", "32", "32",
                              "--spp", "1", "-o", os.path.join(tmp, "stuck.pfm"),
                              "--watchdog", "2"], capture_output=True, text=True, timeout=60)
    except subprocess.TimeoutExpired:
        check(False, "an endless loop with --watchdog 2 ends within 60 s (it ran on)")
        return
    seconds = time.time() - start
    lines = [line for line in run.stderr.splitlines() if STUCK in line]
    check(run.returncode == 1 and seconds < 30,
          f"an endless loop with --watchdog 2 ends with exit status 1 within 30 s "
          f"(status {run.returncode}, {seconds:.1f} s)")
    check(len(lines) == 1 and "labs/uniform.cpp" in lines[0] and "while" in lines[0],
          f"with one line naming labs/uniform.cpp and the likely cause: {run.stderr.strip()!r}")
    check(not os.path.exists(os.path.join(tmp, "stuck.pfm")), "and no image is left behind")
    for bad in ("-1", "soon", "nan"):
        run = subprocess.run([VIEWER, "-c", SCENE, "--watchdog", bad, "-o",
                              os.path.join(tmp, "bad.pfm")], capture_output=True, text=True,
                             timeout=60)
        check(run.returncode == 2 and "--watchdog" in run.stderr and
              run.stderr.count("\n") == 1,
              f"--watchdog {bad} is refused with exit status 2 in one line: {run.stderr.strip()!r}")


def crash_is_named(tmp):
    furnace = os.path.join(MODELS, "furnace.ecs")
    for name in ("branching_no_depth_limit", "branching_crash"):
        for mode in (["-o", os.path.join(tmp, "crash.pfm")], ["--inspect", "8", "8"]):
            run = subprocess.run([os.path.join(MUTANTS, name), "-c", furnace, "--lab",
                                  "branching", "--size", "16", "16", "--spp", "1", *mode],
                                 capture_output=True, text=True, timeout=120)
            lines = [line for line in run.stderr.splitlines() if "crashed:" in line]
            check(run.returncode == -11 and len(lines) == 1 and
                  lines[0].startswith("lab 1 (branching, labs/branching.cpp) crashed: a "
                                      "recursion that never ends"),
                  f"{name} {mode[0]}: ends by SIGSEGV after one line naming labs/branching.cpp "
                  f"(status {run.returncode}): {run.stderr.strip()[-300:]!r}")


def watchdog_leaves_images_alone(tmp):
    images = {}
    for name, option in (("off", ["--watchdog", "0"]), ("short", ["--watchdog", "0.5"]),
                         ("default", [])):
        path = os.path.join(tmp, f"watchdog-{name}.pfm")
        run = subprocess.run([VIEWER, "-c", SCENE, "--lab", "roulette", "--solution", "--size",
                              "64", "48", "--spp", "8", "--seed", "3", "-o", path, *option],
                             capture_output=True, text=True, timeout=120)
        images[name] = open(path, "rb").read() if run.returncode == 0 else run.stderr
    check(images["off"] == images["short"] == images["default"] and
          isinstance(images["off"], bytes),
          "a correct lab renders the same bytes with the watchdog off, at 0.5 s and by default")


def nan_warning_comes_first(tmp):
    mutant = os.path.join(MUTANTS, "roulette_nan")
    # Its NaN comes at depth 2, which this continuation probability reaches often.
    code, text = run_on_terminal([mutant, "-c", SCENE, "--lab", "roulette", "--size", "64", "64",
                                  "--spp", "64", "--continue-prob", "0.5", "-o",
                                  os.path.join(tmp, "nan.pfm")], 120)
    warning = text.find("NaN or infinite samples")
    wrote = text.find("wrote ")
    check(code == 0 and 0 <= warning < wrote,
          f"with NaN samples the warning comes before the render's figures: {text.strip()!r}")
    check(not re.search(r"noise \d", text) and not re.search(r"efficiency \d", text),
          "and no noise or efficiency figure is printed as if it meant something")


def progress_line_on_terminals_only(tmp):
    # A few seconds of rendering: the line appears after half a second.
    argv = [VIEWER, "-c", SCENE, "--lab", "importance", "--solution", "--size", "128", "128",
            "--spp", "256", "--threads", "1", "-o", os.path.join(tmp, "progress.pfm")]
    code, text = run_on_terminal(argv, 300)
    bars = re.findall(r"\r\S*progress\.pfm \[[= ]{30}\] +(\d+)% \d+/\d+ samples, ETA \d+ s", text)
    check(code == 0 and len(bars) >= 2 and bars[-1] == "100",
          f"on a terminal the render draws its progress in place, up to 100% "
          f"({len(bars)} lines: {text.strip()[:160]!r}...)")
    run = subprocess.run(argv, capture_output=True, text=True, timeout=300)
    check(run.returncode == 0 and run.stderr == "",
          f"in a pipe it draws nothing (stderr {run.stderr[:160]!r})")


def render_with_stats(tmp, name, env=None):
    """A render of about a second of CPU time on one thread: (the run, its --stats)."""
    stats = os.path.join(tmp, name + ".json")
    run = subprocess.run([VIEWER, "-c", SCENE, "--lab", "importance", "--solution", "--size", "96",
                          "96", "--spp", "96", "--threads", "1", "-o", os.path.join(tmp, name + ".pfm"),
                          "--stats", stats], capture_output=True, text=True, timeout=300,
                         env=dict(os.environ, **(env or {})))
    return run, json.load(open(stats)) if run.returncode == 0 else {}


def cpu_time_and_its_fallback(tmp):
    run, s = render_with_stats(tmp, "cpu")
    samples = s.get("spp", 0) * s.get("width", 0) * s.get("height", 0)
    check(run.returncode == 0 and s.get("cpu_clock") == "per-thread" and s["cpu_seconds"] > 0
          and abs(s["samples_per_cpu_second"] - samples / s["cpu_seconds"]) <= 1e-6 * samples / s["cpu_seconds"]
          and 0 < s["cpu_share"] <= 1.2 and not s.get("cpu_note"),
          f"--stats has the render threads' CPU time from per-thread clocks, and samples per "
          f"CPU-second of it ({ {k: v for k, v in s.items() if k.startswith('cpu') or 'per_cpu' in k} })")
    check("s of CPU time)" in run.stdout and "samples per CPU-second" in run.stdout
          and "CPU time from the process" not in run.stdout,
          f"the headless line says the CPU time and samples per CPU-second: {run.stdout.strip()[:240]!r}")
    run, s = render_with_stats(tmp, "process", {"PATHLAB_CPU_CLOCK": "process"})
    said = [line for line in run.stdout.splitlines() if "CPU time from the process" in line]
    check(run.returncode == 0 and s.get("cpu_clock", "").startswith("process (no per-thread CPU clock here")
          and s["cpu_seconds"] > 0 and s["samples_per_cpu_second"] > 0 and len(said) == 1
          and "CPU time from the process" in s.get("cpu_note", ""),
          f"without per-thread clocks, the process's clock, said in one line and in --stats: "
          f"{said!r}, {s.get('cpu_clock', '')[:60]!r}")


def main():
    run_in_scratch_folder(cpu_time_and_its_fallback, endless_loop_is_stopped, crash_is_named,
                          watchdog_leaves_images_alone, nan_warning_comes_first,
                          progress_line_on_terminals_only)


if __name__ == "__main__":
    main()
