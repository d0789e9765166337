#!/usr/bin/env python3
"""Lists the tests a ctest run skipped, each with its reason, so that CI's output says what was
not tested: a skipped test shows as passed in ctest's exit status.

Usage: skipped_tests.py CTEST_OUTPUT LAST_TEST_LOG

CTEST_OUTPUT is what ctest printed (its "did not run" list names the skipped tests);
LAST_TEST_LOG is build/Testing/Temporary/LastTest.log, which holds each test's output. A test's
reason is its line that starts with "skipped:" (PathLab's tests print one), else its last line.
"""
import re
import sys


def skipped_tests(ctest_output):
    listed = ctest_output.split("The following tests did not run:", 1)
    if len(listed) < 2:
        return []
    return re.findall(r"^\s*\d+ - (\S+) \(Skipped\)", listed[1], re.MULTILINE)


def reason(log, test):
    block = re.search(r"^\d+/\d+ Test: " + re.escape(test) +
                      r"\n.*?^Output:\n-+\n(.*?)^<end of output>", log, re.MULTILINE | re.DOTALL)
    if not block:
        return "(no output in the log)"
    lines = [line.strip() for line in block.group(1).splitlines() if line.strip()]
    said = [line[len("skipped:"):].strip() for line in lines if line.startswith("skipped:")]
    return (said or lines or ["(no output)"])[-1]


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    try:
        with open(sys.argv[1], errors="replace") as f:
            output = f.read()
        with open(sys.argv[2], errors="replace") as f:
            log = f.read()
    except FileNotFoundError as error:
        print(f"skipped tests: unknown, ctest did not run ({error.filename} is missing)")
        return
    if "Test project " not in output:
        print("skipped tests: unknown, ctest did not run")
        return
    tests = skipped_tests(output)
    if not tests:
        print("skipped tests: none")
        return
    print(f"skipped tests ({len(tests)}), not tested here:")
    for test in tests:
        print(f"  {test}: {reason(log, test)}")


if __name__ == "__main__":
    main()
