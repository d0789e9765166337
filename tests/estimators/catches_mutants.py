#!/usr/bin/env python3
"""The lab tests (tests/estimators, `ctest -L labs`) against buggy labs: ctest estimators.mutants.

Usage: catches_mutants.py --solutions EXE --stubs EXE [--mutant NAME:LAB:STEP:EXE]...

Each EXE holds the estimator tests linked as the student release links them, without the
solutions, so they render the "student" labs linked in (tests/CMakeLists.txt): the solutions,
the stubs of labs/, or the solutions with one lab swapped for the mutant
tests/grader/mutants/NAME/. Checks, each printing PASS/FAIL (the script exits non-zero if any
failed):
- with the solutions as the student's labs, every lab's tests pass;
- with the stubs, every lab's tests fail, saying the lab renders direct light only;
- with a mutant, the tests of its lab (tagged [LAB]) fail and a failure message names its step
  ("TODO STEP"); the tests of the other labs, which are the solutions, pass.
Each mutant's failure messages are printed, so the log shows what a student would read.
"""
import argparse
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import LABS as LAB_NAMES, check, exit_code  # noqa: E402

# The lab tests tag each lab by its number: [lab1] is the first lab of the list.
LABS = tuple(f"lab{number}" for number in range(1, len(LAB_NAMES) + 1))



def run_lab_tests(executable, lab):
    """(passed, the failure lines) of the tests tagged [lab]. Catch's compact reporter writes one
    unwrapped line per failed check, so a step's name is never split across lines."""
    result = subprocess.run([executable, f"[{lab}]", "--reporter", "compact"],
                            capture_output=True, text=True, timeout=240)
    output = result.stdout + result.stderr
    return result.returncode == 0, [line for line in output.splitlines() if "failed" in line]


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
    args = parser.parse_args()

    for lab in LABS:
        passed, lines = run_lab_tests(args.solutions, lab)
        check(passed, f"with the solutions as the student's labs, the {lab} tests pass"
                      + "".join("\n    " + line for line in lines))
    for lab in LABS:
        passed, lines = run_lab_tests(args.stubs, lab)
        check(not passed and any("direct light only" in line for line in lines),
              f"with the stubs, the {lab} tests fail: direct light only")
    for name, lab, step, executable in args.mutant:
        passed, lines = run_lab_tests(executable, lab)
        print(f"{name}: the {lab} tests say\n" + "".join(f"    {line}\n" for line in lines))
        check(not passed, f"{name}: the {lab} tests fail")
        check(any(f"TODO {step}" in line for line in lines),
              f"{name}: a failure of the {lab} tests names TODO {step}")
        for other in LABS:
            if other != lab:
                passed, lines = run_lab_tests(executable, other)
                check(passed, f"{name}: the {other} tests (the solution's) pass"
                              + "".join("\n    " + line for line in lines))
    return exit_code()


if __name__ == "__main__":
    sys.exit(main())
