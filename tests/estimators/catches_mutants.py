#!/usr/bin/env python3
"""The lab tests (tests/estimators, `ctest -L labs`) against buggy labs: ctest estimators.mutants.

Usage: catches_mutants.py --solutions EXE --stubs EXE [--mutant NAME:LAB:STEP:EXE]...
                          [--endless-loop NAME:LAB:EXE]...

Each EXE holds the estimator tests linked as the student release links them, without the
solutions, so they render the "student" labs linked in (tests/estimators/CMakeLists.txt): the
solutions, the stubs of labs/, or the solutions with one lab swapped for the mutant
tests/grader/mutants/NAME/. Checks, each printing PASS/FAIL (the script exits non-zero if any
failed):
- with the solutions as the student's labs, every lab's tests pass;
- with the stubs, every lab's tests fail, saying the lab renders direct light only;
- with a mutant, the tests of its lab (tagged [LAB]) fail and a failure message names its step
  ("TODO STEP"; a STEP that is no step, such as changes_light_non-linearly, is words the message
  must hold, _ for spaces), each failing furnace test naming a cause or saying that none is
  known; and, for the first mutant of each lab, the tests of the other labs, which are the
  solutions, pass (the later mutants of a lab differ from the first in that lab's file only, and
  running every other lab's tests for each of them was most of this test's time);
- with a mutant whose lab never returns (--endless-loop), the tests of its lab end, within a
  bounded time, with the renders' watchdog line naming the lab's file and the likely cause (the
  watchdog shortened to 2 s through PATHLAB_TEST_WATCHDOG_SECONDS, tests/support).
Each mutant's failure messages are printed, so the log shows what a student would read.
"""
import argparse
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import LABS as LAB_NAMES, check, exit_code  # noqa: E402

# The lab tests tag each lab by its number: [lab1] is the first lab of the list.
LABS = tuple(f"lab{number}" for number in range(1, len(LAB_NAMES) + 1))
# What the renders' watchdog says of a lab that never returns (framework/src/render/render_watchdog.cpp).
STUCK = "an endless loop, or recursion that never ends?"



def run_lab_tests(executable, lab):
    """(passed, the failure lines) of the tests tagged [lab]. Catch's compact reporter writes one
    unwrapped line per failed check, so a step's name is never split across lines."""
    result = subprocess.run([executable, f"[{lab}]", "--reporter", "compact"],
                            capture_output=True, text=True, timeout=240)
    output = result.stdout + result.stderr
    return result.returncode == 0, [line for line in output.splitlines() if "failed" in line]


def stopped_endless_loop(name, lab, executable):
    """The tests of `lab` with a lab that never returns: they end by the watchdog, which says
    why, and not by this script's time limit."""
    environment = dict(os.environ, PATHLAB_TEST_WATCHDOG_SECONDS="2")
    start = time.time()
    try:
        result = subprocess.run([executable, f"[{lab}]", "--reporter", "compact"],
                                capture_output=True, text=True, timeout=120, env=environment)
    except subprocess.TimeoutExpired:
        check(False, f"{name}: the {lab} tests end within 120 s (they ran on)")
        return
    seconds = time.time() - start
    output = result.stdout + result.stderr
    lines = [line for line in output.splitlines() if STUCK in line]
    print(f"{name}: the {lab} tests say\n" + "".join(f"    {line}\n" for line in lines))
    check(result.returncode != 0 and seconds < 60,
          f"{name}: the {lab} tests fail within 60 s (status {result.returncode}, {seconds:.0f} s)")
    check(any(f"labs/{LAB_NAMES[LABS.index(lab)]}.cpp" in line for line in lines),
          f"{name}: they say '{STUCK}', naming the lab's file")


def endless_loop(text):
    name, lab, executable = text.split(":", 2)
    if lab not in LABS:
        raise argparse.ArgumentTypeError(f"'{text}': {lab} is not one of {', '.join(LABS)}")
    return name, lab, executable


def mutant(text):
    name, lab, step, executable = text.split(":", 3)
    if lab not in LABS:
        raise argparse.ArgumentTypeError(f"'{text}': {lab} is not one of {', '.join(LABS)}")
    return name, lab, step, executable


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--solutions", required=True, help="the tests with the solutions")
    parser.add_argument("--stubs", required=True, help="the tests with the stubs of labs/")
    parser.add_argument("--mutant", type=mutant, action="append", default=[],
                        metavar="NAME:LAB:STEP:EXE", help="the tests with a mutant lab")
    parser.add_argument("--endless-loop", type=endless_loop, action="append", default=[],
                        metavar="NAME:LAB:EXE", help="the tests with a lab that never returns")
    args = parser.parse_args()

    for lab in LABS:
        passed, lines = run_lab_tests(args.solutions, lab)
        check(passed, f"with the solutions as the student's labs, the {lab} tests pass"
                      + "".join("\n    " + line for line in lines))
    for lab in LABS:
        passed, lines = run_lab_tests(args.stubs, lab)
        check(not passed and any("direct light only" in line for line in lines),
              f"with the stubs, the {lab} tests fail: direct light only")
    labs_with_others_checked = set()
    for name, lab, step, executable in args.mutant:
        passed, lines = run_lab_tests(executable, lab)
        print(f"{name}: the {lab} tests say\n" + "".join(f"    {line}\n" for line in lines))
        check(not passed, f"{name}: the {lab} tests fail")
        # A step (lab3.2) is named as "TODO lab3.2"; a bug of no step by its words, _ for spaces.
        words = f"TODO {step}" if step.startswith("lab") else step.replace("_", " ")
        check(any(words in line for line in lines), f"{name}: a failure of the {lab} tests says {words!r}")
        furnaces = [line for line in lines if "furnace" in line and "expected" in line]
        check(all("match" in line or "No bug the grader knows" in line or "Likely cause" in line
                  for line in furnaces),
              f"{name}: each failing furnace test names a cause or says none is known")
        if lab in labs_with_others_checked:
            continue
        labs_with_others_checked.add(lab)
        for other in LABS:
            if other != lab:
                passed, lines = run_lab_tests(executable, other)
                check(passed, f"{name}: the {other} tests (the solution's) pass"
                              + "".join("\n    " + line for line in lines))
    for name, lab, executable in args.endless_loop:
        stopped_endless_loop(name, lab, executable)
    return exit_code()


if __name__ == "__main__":
    sys.exit(main())
