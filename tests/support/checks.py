"""What PathLab's Python tests share: how a check is reported and counted, the list of labs, the
arguments of a test that packages the kit, and a test's checks run in one scratch folder.

A test prints PASS or FAIL for each check and exits non-zero at the end if any failed, so ctest's
log shows every check, not only the first that failed."""
import argparse
import os
import sys
import tempfile

KIT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def _lab_lines():
    """The fields of each lab's line in the one list the build, the registry and the viewer
    follow (framework/lab_list.txt: a lab per line, its name first; # starts a comment line)."""
    with open(os.path.join(KIT, "framework", "lab_list.txt"), encoding="utf-8") as f:
        lines = [line.split() for line in f]
    labs = [fields for fields in lines if fields and not fields[0].startswith("#")]
    if not labs:
        raise RuntimeError("framework/lab_list.txt names no lab")
    return labs


LABS = tuple(fields[0] for fields in _lab_lines())
# The labs that end paths by Russian roulette (the list's "unbiased"), in order.
UNBIASED = tuple(fields[0] for fields in _lab_lines() if fields[2] == "unbiased")
# The labs that write a glossy lobe (the list's fourth field, "lobe"), in order.
LOBE = tuple(fields[0] for fields in _lab_lines() if fields[3:] == ["lobe"])

failures = []


def check(condition, what):
    """Says PASS or FAIL with `what`; a failure makes the test fail at the end (exit_code)."""
    print(("PASS " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def exit_code(label="", seconds=None):
    """1 if a check failed, else 0, after a line saying how many failed (and how long it took,
    if `seconds` is given). The failed checks are said again above that line: a log shown only
    by its end (CI's summary, a test run inside another) still shows what failed."""
    took = f" in {seconds:.0f} s" if seconds is not None else ""
    for what in failures:
        print("FAILED: " + what)
    print(f"{label}{len(failures)} check(s) failed{took}")
    return 1 if failures else 0


def finish():
    sys.exit(exit_code())


def run_in_scratch_folder(*checks):
    """Calls each of `checks` in turn with the path of one scratch folder, which is removed
    afterwards, then exits as finish() does: a test's main() when all its checks write their
    files into one folder."""
    with tempfile.TemporaryDirectory() as scratch:
        for each in checks:
            each(scratch)
    finish()


def package_test_arguments():
    """The arguments of a test that packages the kit and tries the package (the student release,
    the Gradescope autograder): --source, the instructor's kit (made absolute), and --keep, to
    keep the scratch folder for a look afterwards."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--source", required=True, help="the instructor's kit")
    parser.add_argument("--keep", action="store_true", help="keep the scratch folder")
    args = parser.parse_args()
    args.source = os.path.abspath(args.source)
    return args
