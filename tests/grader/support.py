"""What the grader's end-to-end tests share: their command line, how a check is reported and
counted, and writing the files they make."""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
# The tests import these from here.
from checks import LABS, LOBE, UNBIASED, check, exit_code, finish  # noqa: E402,F401


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


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def busy_processes(count):
    """`count` processes that spin on a core each, to load the machine: each dies with this test
    (Linux's parent-death signal), even when the test itself is killed by ctest's timeout or a
    SIGKILL, which a `finally` block never sees; left running, they would slow every later test."""
    import ctypes
    import signal
    import subprocess

    def die_with_parent():
        PR_SET_PDEATHSIG = 1
        ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGKILL)

    return [subprocess.Popen([sys.executable, "-c", "while True: pass"], preexec_fn=die_with_parent)
            for _ in range(count)]
