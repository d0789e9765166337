#!/usr/bin/env python3
"""The list of labs stops the build at a line that is not a lab, ctest `docs.lab_list`.

Usage: lab_list_test.py --source KIT --cmake CMAKE

framework/lab_list.txt is read by cmake/lab_list.cmake when the kit is configured; run as a script
(`cmake -DPATHLAB_LAB_LIST=FILE -P cmake/lab_list.cmake`), it reads and checks a list the same
way. The kit's own list must give the labs the Python tests read (checks.LABS), with Windows line
endings too; each broken copy of it (a field missing, a name that is not an identifier, a lab
named twice, ...) must fail with a message naming the file, the line and the problem, as its
header comment promises.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import LABS, check, exit_code  # noqa: E402

# (what is wrong, the line put in after the kit's second lab, what the message says after
# "FILE:LINE: "); {enumerator} is the kit's first lab's.
BROKEN_LINES = [
    ("a field missing", "fifth Fifth", "2 field(s) where a lab has 3 or 4"),
    ("a field too many", "fifth Fifth unbiased lobe 5", "5 field(s) where a lab has 3 or 4"),
    ("routines other than a lobe", "fifth Fifth unbiased 5", "the fourth field `5` is not `lobe`"),
    ("a name that is not an identifier", "5th Fifth unbiased", "`5th` is not a C++ identifier"),
    ("an enumerator that is not an identifier", "fifth Fifth-Lab unbiased",
     "`Fifth-Lab` is not a C++ identifier"),
    ("an estimate that is neither", "fifth Fifth biased",
     "the estimate `biased` is neither depth-limited nor unbiased"),
    ("a lab named twice", f"{LABS[0]} Fifth unbiased", f"the lab `{LABS[0]}` again"),
    ("an enumerator named twice", "fifth {enumerator} unbiased",
     "the enumerator `{enumerator}` again"),
    ("a line continued as the C macro's were", "fifth Fifth unbiased \\",
     "a ';', '[', ']' or '\\', which the list of labs cannot hold"),
    ("an unmatched bracket in a comment", "# the fifth lab [draft",
     "a ';', '[', ']' or '\\', which the list of labs cannot hold"),
]


def read_list(cmake, source, path):
    """(exit status, what cmake printed, whitespace collapsed: CMake wraps its messages)."""
    result = subprocess.run([cmake, f"-DPATHLAB_LAB_LIST={path}", "-P",
                             os.path.join(source, "cmake", "lab_list.cmake")],
                            capture_output=True, text=True)
    return result.returncode, re.sub(r"\s+", " ", result.stdout + result.stderr)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", required=True)
    parser.add_argument("--cmake", required=True)
    args = parser.parse_args()
    kit_list = os.path.join(args.source, "framework", "lab_list.txt")
    with open(kit_list, encoding="utf-8") as f:
        lines = f.read().splitlines()

    status, output = read_list(args.cmake, args.source, kit_list)
    check(status == 0 and f"labs: {' '.join(LABS)}" in output,
          f"the kit's list gives the labs {', '.join(LABS)}: {output.strip()}")

    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "lab_list.txt")
        with open(path, "w", encoding="utf-8", newline="\r\n") as f:
            f.write("\n".join(line.replace("    ", "\t") for line in lines) + "\n")
        status, output = read_list(args.cmake, args.source, path)
        check(status == 0 and f"labs: {' '.join(LABS)}" in output,
              f"with Windows line endings and tabs, the same labs: {output.strip()}")

        # After the second lab, so that the line number counts the comments and empty lines.
        second = [i for i, line in enumerate(lines) if line.split()[:1] == [LABS[1]]][0]
        enumerator = [line.split()[1] for line in lines if line.split()[:1] == [LABS[0]]][0]
        for what, bad, says in BROKEN_LINES:
            bad, says = bad.format(enumerator=enumerator), says.format(enumerator=enumerator)
            with open(path, "w", encoding="utf-8") as f:
                f.write("\n".join(lines[:second + 1] + [bad] + lines[second + 1:]) + "\n")
            status, output = read_list(args.cmake, args.source, path)
            expected = f"{path}:{second + 2}: {says}"
            check(status != 0 and expected in output,
                  f"{what} ({bad!r}) stops CMake with \"{expected}\"" +
                  ("" if status != 0 and expected in output else f"; it said: {output.strip()}"))

        with open(path, "w", encoding="utf-8") as f:
            f.write("\n".join(line for line in lines if line.startswith("#")) + "\n")
        status, output = read_list(args.cmake, args.source, path)
        check(status != 0 and f"{path}: no lab in it" in output,
              f"a list of comments only stops CMake with \"{path}: no lab in it\"" +
              ("" if status != 0 else f"; it said: {output.strip()}"))
    return exit_code()


if __name__ == "__main__":
    sys.exit(main())
