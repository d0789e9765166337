#!/usr/bin/env python3
"""Every C++ file of the kit is laid out as .clang-format says, ctest `format`.

Usage: format_test.py --source KIT

Runs clang-format --dry-run on the C++ files git tracks (all of them when the kit is not a git
checkout), except the grader's hostile labs, which are laid out as an attacker would write them.
clang-format's output differs from one major version to the next, so the check runs only with
the version the kit was formatted with (FORMATTED_WITH, also named in .clang-format); with
another, or none, it is skipped (exit 77) saying which it found. To lay a file out:
`clang-format -i FILE`.
"""
import argparse
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys

SKIPPED = 77  # the test's SKIP_RETURN_CODE (tests/CMakeLists.txt)
FORMATTED_WITH = 14
EXTENSIONS = (".cpp", ".h")
LEFT_ALONE = ("tests/grader/hostile/",)


def clang_format():
    for name in (f"clang-format-{FORMATTED_WITH}", "clang-format"):
        path = shutil.which(name)
        if not path:
            continue
        version = subprocess.run([path, "--version"], capture_output=True, text=True).stdout
        major = re.search(r"version (\d+)", version)
        if major and int(major.group(1)) == FORMATTED_WITH:
            return path, None
        found = version.strip()
    else:
        found = None
    return None, found


def kit_files(source):
    if os.path.isdir(os.path.join(source, ".git")):
        listed = subprocess.run(["git", "ls-files"], cwd=source, capture_output=True, text=True,
                                check=True).stdout.splitlines()
    else:
        listed = [os.path.relpath(os.path.join(folder, name), source)
                  for folder, _, names in os.walk(source) for name in names]
    return sorted(f for f in listed if f.endswith(EXTENSIONS) and not f.startswith(LEFT_ALONE)
                  and not f.startswith(("build/", "third_party/")))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", required=True)
    args = parser.parse_args()
    tool, found = clang_format()
    if not tool:
        print(f"skipped: needs clang-format {FORMATTED_WITH}, found "
              f"{found or 'none'} (apt install clang-format)")
        return SKIPPED
    files = kit_files(args.source)

    def violations(path):
        result = subprocess.run([tool, "--dry-run", "--Werror", path], cwd=args.source,
                                capture_output=True, text=True)
        return path, result.returncode, result.stderr.count("clang-format-violations")

    # One clang-format per file, on every core: a process each, most of the time is start-up.
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        results = list(pool.map(violations, files))
    unformatted = [(path, count) for path, status, count in results if status != 0]
    for path, lines in unformatted:
        print(f"FAIL: {path}: {lines} place(s) laid out otherwise than .clang-format says "
              f"(clang-format -i {path})")
    print(f"{len(files) - len(unformatted)} of {len(files)} C++ files laid out as .clang-format "
          f"says ({os.path.basename(tool)})")
    return 1 if unformatted else 0


if __name__ == "__main__":
    sys.exit(main())
