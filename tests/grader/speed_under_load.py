#!/usr/bin/env python3
"""The speed check's false-fail rate on a busy machine, measured: the reference solutions,
submitted as a student's labs N times (40 by default), graded by `grader batch` with 2 jobs while
four busy processes load the machine. Every one of the 4N speed checks must pass (the check
fails a lab only when its ratio lies below the threshold with confidence); prints, per lab, the
spread of the timed pairs' ratios in CPU time, which the check uses, and in wall-clock time,
which it used before.

Slow (a quarter of an hour to an hour on 2 cores): `make test-slow`, or run by hand:
    tests/grader/speed_under_load.py --build build --source . [--gradings 40] [--load 4]
"""
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

from support import LABS, arguments, busy_processes, check, finish, grader

args = arguments((["--gradings"], {"type": int, "default": 40}),
                 (["--load"], {"type": int, "default": 4, "help": "busy processes to start"}))
GRADER = grader(args)


def rubric(root):
    """The kit's rubric, lighter where speed does not depend on it: the VI2 box alone (the speed
    scene), no variants."""
    r = json.load(open(os.path.join(args.source, "grader", "rubric.json")))
    r["correctness"]["scenes"] = ["cornell_box_VI2_Specular"]
    r["hidden_scenes"]["variants"] = 0
    path = os.path.join(root, "rubric.json")
    json.dump(r, open(path, "w"))
    return path


def spread(values):
    return f"{min(values):.2f} / {statistics.median(values):.2f} / {max(values):.2f}"


def main():
    with tempfile.TemporaryDirectory() as root:
        os.chmod(root, 0o755)
        subs = os.path.join(root, "subs")
        for k in range(args.gradings):
            shutil.copytree(os.path.join(args.source, "solutions"), os.path.join(subs, f"copy{k:03d}"))
        out = os.path.join(root, "out")
        load = busy_processes(args.load)
        started = time.time()
        try:
            run = subprocess.run([GRADER, "batch", subs, "--out", out, "--jobs", "2", "--rubric", rubric(root),
                                  "--scenes", "none", "--no-race-check"], capture_output=True, text=True)
        finally:
            for process in load:
                process.kill()
        print(run.stdout + run.stderr[-2000:])
        check(run.returncode == 0, "the batch ran")
        fails, cpu, wall, pairs = {lab: 0 for lab in LABS}, {lab: [] for lab in LABS}, {lab: [] for lab in LABS}, []
        for k in range(args.gradings):
            folder = os.path.join(out, "submissions", f"copy{k:03d}")
            result = json.load(open(os.path.join(folder, "result.json")))
            for lab in LABS:
                fails[lab] += not result["labs"][lab]["checks"]["speed"]["passed"]
            for m in json.load(open(os.path.join(folder, "measurements.json")))["labs"]:
                t = m["speed"]
                pairs.append(len(t["student"]))
                cpu[m["lab"]] += [s / r for s, r in zip(t["student"], t["solution"])]
                wall[m["lab"]] += [r / s for s, r in zip(t["student_wall_seconds"], t["solution_wall_seconds"])]
        print(f"{args.gradings} gradings of the solutions under {args.load} busy processes on "
              f"{os.cpu_count()} cores, {time.time() - started:.0f} s; pairs per lab: "
              f"{min(pairs)} to {max(pairs)}")
        print("| lab | speed fails | pair ratio, CPU time (min / median / max) | pair ratio, wall time |")
        print("|---|---|---|---|")
        for lab in LABS:
            print(f"| {lab} | {fails[lab]} of {args.gradings} | {spread(cpu[lab])} | {spread(wall[lab])} |")
        check(sum(fails.values()) == 0, "no speed check of the reference solutions failed")
    finish()


main()
