"""What the platform tests that build the kit again (tests/platforms/*_test.py) share: their
arguments, finding clang, and their steps, each timed."""
import argparse
import os
import shutil
import subprocess
import sys
import time

SKIP = 77  # the tests' SKIP_RETURN_CODE (tests/CMakeLists.txt)


def build_arguments(description):
    """--source, --build (made fresh) and --jobs."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--source", required=True, help="the kit's source folder")
    parser.add_argument("--build", required=True, help="the folder to build in (made fresh)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    return parser.parse_args()


def clang_or_skip():
    """clang++'s path; exits the test as skipped, saying why, where there is none."""
    compiler = shutil.which("clang++")
    if not compiler:
        print("skipped: clang++ is not installed (apt install clang)")
        sys.exit(SKIP)
    return compiler


class TimedSteps:
    """The steps of one test, each timed: a failing step stops the test with every time measured
    so far, since on a shared machine the times say as much as the failure."""

    def __init__(self, name):
        self.name = name  # prefixes every line printed: "clang + libc++", "TSan"
        self.timings = []

    def run(self, command, cwd, what, env=None):
        """Runs `command` in `cwd`; exits the test (status 1) if it fails."""
        print("$ " + " ".join(command), flush=True)
        start = time.monotonic()
        result = subprocess.run(command, cwd=cwd, env=env)
        self.timings.append((what, time.monotonic() - start))
        if result.returncode != 0:
            print(f"{self.name}: {what} failed (exit {result.returncode})", flush=True)
            self.report()
            sys.exit(1)

    def report(self):
        for what, seconds in self.timings:
            print(f"{self.name}: {what}: {seconds:.0f} s")
