"""What the grader's end-to-end tests share: their command line, how a check is reported and
counted, and writing the files they make."""
import argparse
import os
import sys

LABS = ("branching", "uniform", "importance", "roulette")

failures = []


def arguments(*options, source=True):
    """The test's arguments: --build (the build folder, made absolute), --source (the kit's
    folder, absolute) unless `source` is False, and `options`, each the arguments of one
    ArgumentParser.add_argument call as (names, keywords)."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", required=True)
    if source:
        parser.add_argument("--source", required=True)
    for names, keywords in options:
        parser.add_argument(*names, **keywords)
    args = parser.parse_args()
    args.build = os.path.abspath(args.build)
    if source:
        args.source = os.path.abspath(args.source)
    return args


def grader(args):
    """The grader executable of the build under test."""
    return os.path.join(args.build, "grader")


def check(condition, what):
    """Says PASS or FAIL with `what`; a failure makes the test fail at the end (exit_code)."""
    print(("PASS " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def exit_code():
    """1 if a check failed (after saying how many), else 0."""
    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    return 0


def finish():
    sys.exit(exit_code())


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)
