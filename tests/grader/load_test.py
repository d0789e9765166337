#!/usr/bin/env python3
"""A correct but slow lab graded while the machine is kept busy: its renders take several times
their CPU time in wall-clock time, yet the grader's limits, on CPU time and on progress, let them
finish. The lab keeps its correctness and noise points and loses only its speed points, and its
feedback says "too slow", never "endless loop" or "time limit".

The lab is lab 2's reference solution with a few microseconds of busy work per camera ray: about
4 s of CPU time per correctness render, under the test rubric's 8 s per render thread. The load,
four busy processes on the machine's cores, starts once the grading has begun (after anything
the grader measures at its start), as a class graded beside other work meets it.
"""
import json
import os
import subprocess
import sys
import tempfile
import time

from support import arguments, busy_processes, check, finish, grader, write

args = arguments()
GRADER = grader(args)

# Busy work of the lab's own per camera ray, which the compiler cannot drop: calibrated below to
# about BUSY_MICROSECONDS.
SLOW_LAB = """
#include <cmath>
namespace {{
volatile double sink = 0;
void busyWork() {{
    double sum = 0;
    for (int i = 1; i <= {iterations}; ++i) sum += std::sqrt(static_cast<double>(i));
    sink = sink + sum;
}}
}} // namespace
"""


def slow_lab(iterations):
    """Lab 2's reference solution with `iterations` of busy work at each camera ray."""
    text = open(os.path.join(args.source, "solutions", "uniform.cpp")).read()
    signature = "Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {\n"
    check(signature in text, "solutions/uniform.cpp has the line the slow lab is made at")
    return text.replace(signature, SLOW_LAB.format(iterations=iterations) + signature
                        + "    if (depth == 0) busyWork();\n", 1)


def rubric(root):
    r = json.load(open(os.path.join(args.source, "grader", "rubric.json")))
    r["correctness"].update({"seeds": 4, "scenes": ["cornell_box_VI2_Specular", "furnace"]})
    r["speed"]["runs"] = 2
    r["limits"]["seconds_per_run"] = 8
    r["hidden_scenes"]["variants"] = 0
    path = os.path.join(root, "rubric.json")
    json.dump(r, open(path, "w"))
    return path


def main():
    with tempfile.TemporaryDirectory() as root:
        os.chmod(root, 0o755)
        submission = os.path.join(root, "erin")
        # About 4 s of CPU time per correctness render of the VI2 box: 64x64 x 32 spp x 4 seeds
        # = 524,288 camera rays at about 7 microseconds each.
        write(os.path.join(submission, "uniform.cpp"), slow_lab(6000))
        out = os.path.join(root, "out")
        load = []
        try:
            grading = subprocess.Popen([GRADER, "submission", submission, "--out", out, "--rubric", rubric(root),
                                        "--scenes", "none", "--no-race-check"],
                                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            time.sleep(1)
            load = busy_processes(4)
            started = time.time()
            output, _ = grading.communicate(timeout=1200)
            seconds = time.time() - started
        finally:
            for process in load:
                process.kill()
        print(output)
        feedback = json.load(open(os.path.join(out, "feedback.json")))
        uniform = next(lab for lab in feedback["labs"] if lab["lab"] == "uniform")
        checks = {c["name"]: c for c in uniform["checks"]}
        words = json.dumps(uniform)
        check(checks["correctness"]["passed"] and checks["noise"]["passed"],
              "a correct, slow lab graded under load keeps its correctness and noise points "
              f"({checks['correctness']['summary'][:120]})")
        result = json.load(open(os.path.join(out, "result.json")))
        diagnoses = {(d["lab"], d["check"]): d["diagnosis"] for d in result["diagnoses"]}
        check(not checks["speed"]["passed"] and diagnoses.get(("uniform", "speed")) == "too slow"
              and "slower than the reference" in words,
              f"... and loses only its speed points, as too slow ({checks['speed']['summary'][:160]})")
        check("endless loop" not in words and "time limit" not in words and "wall-clock" not in words,
              "its feedback blames no endless loop and no time limit")
        print(f"graded under a load of 4 busy processes in {seconds:.0f} s; by phase: {result['seconds_by_phase']}")
    finish()


main()
