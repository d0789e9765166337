"""The steps of a platform test (tests/platforms/*_test.py), each timed: a failing step stops the
test with every time measured so far, since on a shared machine the times say as much as the
failure."""
import subprocess
import sys
import time


class TimedSteps:
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
