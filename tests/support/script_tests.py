"""What the tests of the kit's scripts (make convergence, make sweep: scripts/NAME.py) share: their
arguments, the script imported to try its functions directly, runs of it and of make as a
student's shell runs them, the checks every such script passes (a run that succeeds, bad input
refused in one line with nothing written) and the reading of the CSV files it writes."""
import argparse
import csv
import importlib
import os
import subprocess
import sys

from checks import check


def script_test_arguments():
    """--build, the build folder, and --source, the kit whose scripts/ is tested."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", required=True)
    parser.add_argument("--source", required=True)
    return parser.parse_args()


def import_script(source, name):
    """(path, module) of the kit's scripts/NAME.py, imported as a module."""
    path = os.path.join(source, "scripts", name + ".py")
    sys.path.insert(0, os.path.dirname(path))
    return path, importlib.import_module(name)


def run(arguments, cwd=None):
    """Runs `arguments` as a student's shell would: without the variables of the make that may be
    running this test (ctest under `make test`), which would change what a nested make does."""
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    return subprocess.run(arguments, capture_output=True, text=True, cwd=cwd, env=env)


def close(a, b, tolerance):
    """Whether a and b differ by at most `tolerance` of the larger (the CSVs' rounding)."""
    return abs(a - b) <= tolerance * max(abs(a), abs(b))


def read_csv(path):
    """The rows of a CSV file with a header, as dicts."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def check_succeeded(result, what):
    """Checks that the run `result` exited 0, a failure showing the end of what it printed; returns
    whether it did."""
    succeeded = result.returncode == 0
    check(succeeded, f"{what}: exit 0" +
          ("" if succeeded else f": {result.stdout[-600:]}{result.stderr[-600:]}"))
    return succeeded


def check_script_refuses(script, build, options, words, scratch):
    """`script` with `options` (shell words) exits 2 with one line on stderr holding `words`, and
    writes nothing: no output folder."""
    out = os.path.join(scratch, "bad")
    result = run(["sh", "-c", f"{sys.executable} {script} --build {build} {options} --out {out}"])
    lines = result.stderr.strip().splitlines()
    check(result.returncode == 2 and len(lines) == 1 and words in lines[0] and
          not result.stdout and not os.path.exists(out),
          f"{os.path.basename(script)} {options}: exit 2, one line naming it, nothing written: "
          f"{result.returncode} {lines}")


def check_make_refuses(source, target, variables, words, scratch):
    """`make TARGET VARIABLES...` in the kit exits 2 with one line of its own (`make TARGET: ...`)
    holding `words`, checked before anything is configured or built: no build folder."""
    build = os.path.join(scratch, "make-build")
    result = run(["make", "--no-print-directory", target, f"BUILD={build}", *variables], cwd=source)
    ours = [line for line in result.stderr.splitlines() if line.startswith(f"make {target}:")]
    check(result.returncode == 2 and len(ours) == 1 and words in ours[0] and
          not os.path.exists(build),
          f"make {target} {' '.join(variables)}: exit 2, one line naming it, nothing written: "
          f"{result.returncode} {ours}")
