#!/usr/bin/env python3
"""The grader's and the framework's sources are in folders by concern, each including only those
its README allows, ctest `docs.grader_folders` and `docs.framework_folders`.

Usage: source_folders_test.py --source KIT --house grader|framework

A house's source folder (grader/src/, framework/src/) holds folders only. Each folder's README.md
says, in a sentence "May include: `a/`, `b/`." (or "May include: no other folder of the
grader."), which other folders its files may include; an include of a folder not named there
fails, and so does an include by a bare name of a file that is not beside the includer. The
allowed includes must form floors (no folder reaches, through others, back to itself), so that
no folder includes one above it.

The grader's headers are included by their folder ("checks/rubric.h"). The framework's are under
framework/include/pathlab/, in a folder of the same name as their sources' ("pathlab/render/
renderer.h" for src/render/renderer.cpp), except the student API: pathlab/ itself holds exactly
the headers pathlab/lab.h reaches, which include nothing else and which every folder may include.

Before the kit, a made-up tree checks that the checker reports an include that goes up and a bare
one.
"""
import argparse
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import check, exit_code  # noqa: E402

MAY_INCLUDE = re.compile(r"May\s+include:(.*?)\.(?:\s|$)", re.S)
QUOTED_INCLUDE = re.compile(r'^#include "([^"]+)"', re.M)
# The header CMake writes from framework/lab_list.txt into the build's pathlab/ (lab.h reaches it).
GENERATED_API = {"lab_list.h"}


class House:
    """Where a house's sources and headers are, and which folder an include reaches."""

    def __init__(self, src, headers=None, prefix=""):
        self.src, self.headers, self.prefix = src, headers, prefix

    def folder_of(self, included):
        """The folder an include names, "" for the student API, None for a bare name."""
        if not included.startswith(self.prefix):
            return None
        rest = included[len(self.prefix):].split("/")
        if len(rest) == 1:
            return "" if self.prefix else None
        return rest[0]

    def files(self, folder):
        roots = [os.path.join(self.src, folder)]
        if self.headers:
            roots.append(os.path.join(self.headers, folder))
        for root_folder in roots:
            for root, _, files in os.walk(root_folder):
                for name in sorted(f for f in files if f.endswith((".cpp", ".h"))):
                    yield os.path.join(root, name)


def allowed_folders(src):
    """{folder: the folders its README allows}, or a problem per folder without the sentence."""
    allowed, problems = {}, []
    for folder in sorted(os.listdir(src)):
        readme = os.path.join(src, folder, "README.md")
        if not os.path.isdir(os.path.join(src, folder)):
            problems.append(f"{folder}: a file outside the folders")
        elif not os.path.isfile(readme):
            problems.append(f"{folder}/: no README.md")
        elif not (sentence := MAY_INCLUDE.search(open(readme).read())):
            problems.append(f"{folder}/README.md: no sentence \"May include: ...\"")
        else:
            allowed[folder] = set(re.findall(r"`([a-z_]+)/`", sentence.group(1)))
    return allowed, problems


def floors(allowed):
    """The folders from the top floor down, or None when the allowed includes form a cycle."""
    placed, order = set(), []
    while len(placed) < len(allowed):
        # Bottom up: a folder's floor is the lowest above every folder it may include.
        floor = sorted(f for f in allowed if f not in placed and allowed[f] <= placed)
        if not floor:
            return None
        placed.update(floor)
        order.insert(0, floor)
    return order


def include_problems(house, allowed):
    problems = []
    for folder in allowed:
        for path in house.files(folder):
            shown = os.path.relpath(path, os.path.dirname(house.src))
            for included in QUOTED_INCLUDE.findall(open(path).read()):
                reached = house.folder_of(included)
                if reached is None:
                    if not os.path.exists(os.path.join(os.path.dirname(path), included)):
                        problems.append(f"{shown}: includes \"{included}\" without its folder")
                elif reached in allowed and reached != folder and reached not in allowed[folder]:
                    problems.append(f"{shown}: includes \"{included}\", which {folder}/README.md "
                                    "does not allow")
    return problems


def api_problems(api_folder):
    """The student API's folder: exactly what lab.h reaches, which includes nothing else."""
    present = {f for f in os.listdir(api_folder) if f.endswith(".h")}
    reached, problems, todo = set(), [], ["lab.h"]
    while todo:
        header = todo.pop()
        if header in reached or header in GENERATED_API:
            continue
        reached.add(header)
        if header not in present:
            problems.append(f"pathlab/{header}: lab.h reaches it, but it is not in pathlab/")
            continue
        for included in QUOTED_INCLUDE.findall(open(os.path.join(api_folder, header)).read()):
            if not re.fullmatch(r"pathlab/[a-z_0-9]+\.h", included):
                problems.append(f"pathlab/{header}: includes \"{included}\", which is not the "
                                "student API")
            else:
                todo.append(included.split("/")[1])
    problems += [f"pathlab/{h}: not reached from lab.h; it belongs in a folder by its concern"
                 for h in sorted(present - reached)]
    return problems


def all_problems(house):
    allowed, problems = allowed_folders(house.src)
    if floors(allowed) is None:
        problems.append("the READMEs' allowed includes form a cycle: no floors")
    if house.headers:
        problems += [f"{os.path.relpath(os.path.join(house.headers, f), house.src)}: a header "
                     "folder with no source folder of its name"
                     for f in sorted(os.listdir(house.headers))
                     if os.path.isdir(os.path.join(house.headers, f)) and f not in allowed]
        problems += api_problems(house.headers)
    return problems + include_problems(house, allowed)


def self_test():
    with tempfile.TemporaryDirectory() as src:
        for folder, may, source in (("high", "`low/`", '#include "low/a.h"\n'),
                                    ("low", "no other folder", '#include "high/b.h"\n#include "c.h"\n')):
            os.makedirs(os.path.join(src, folder))
            open(os.path.join(src, folder, "README.md"), "w").write(f"May include: {may}.\n")
            open(os.path.join(src, folder, "a.h"), "w").write(source)
        reported = all_problems(House(src))
    check(len(reported) == 2 and "high/b.h" in reported[0] and "without its folder" in reported[1],
          f"the checker reports the made-up tree's include that goes up and its bare include, and "
          f"nothing else: {reported}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", required=True)
    parser.add_argument("--house", choices=("grader", "framework"), required=True)
    args = parser.parse_args()
    self_test()
    src = os.path.join(args.source, args.house, "src")
    if args.house == "framework":
        house = House(src, os.path.join(args.source, "framework", "include", "pathlab"), "pathlab/")
    else:
        house = House(src)
    allowed, _ = allowed_folders(src)
    order = floors(allowed)
    problems = all_problems(house)
    check(not problems, f"{args.house}/src/: every include goes sideways or down the floors "
          f"{' > '.join('/'.join(floor) for floor in order or [])}"
          + (" > the student API (pathlab/*.h)" if house.headers else "")
          + "".join(f"\n    {p}" for p in problems))
    return exit_code()


if __name__ == "__main__":
    sys.exit(main())
