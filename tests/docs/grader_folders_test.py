#!/usr/bin/env python3
"""The grader's source is in folders by concern, each including only those its README allows,
ctest `docs.grader_folders`.

Usage: grader_folders_test.py --source KIT

grader/src/ holds folders only. Each folder's README.md says, in a sentence "May include: `a/`,
`b/`." (or "May include: no other folder of the grader."), which other folders its files may
include; an include of a folder not named there, or of a grader header by its bare name, fails.
The allowed includes must form floors (no folder reaches, through others, back to itself), so
that no folder includes one above it. Before the kit, a made-up tree checks that the checker
reports an include that goes up and a bare one.
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


def include_problems(src, allowed):
    problems = []
    for folder in allowed:
        for root, _, files in os.walk(os.path.join(src, folder)):
            for name in sorted(f for f in files if f.endswith((".cpp", ".h"))):
                path = os.path.relpath(os.path.join(root, name), src)
                for included in QUOTED_INCLUDE.findall(open(os.path.join(root, name)).read()):
                    first = included.split("/")[0]
                    if "/" not in included:
                        problems.append(f"{path}: includes \"{included}\" without its folder")
                    elif first in allowed and first != folder and first not in allowed[folder]:
                        problems.append(f"{path}: includes \"{included}\", which {folder}/README.md "
                                        "does not allow")
    return problems


def all_problems(src):
    allowed, problems = allowed_folders(src)
    if floors(allowed) is None:
        problems.append("the READMEs' allowed includes form a cycle: no floors")
    return problems + include_problems(src, allowed)


def self_test():
    with tempfile.TemporaryDirectory() as src:
        for folder, may, source in (("high", "`low/`", '#include "low/a.h"\n'),
                                    ("low", "no other folder", '#include "high/b.h"\n#include "a.h"\n')):
            os.makedirs(os.path.join(src, folder))
            open(os.path.join(src, folder, "README.md"), "w").write(f"May include: {may}.\n")
            open(os.path.join(src, folder, "a.h"), "w").write(source)
        reported = all_problems(src)
    check(len(reported) == 2 and "high/b.h" in reported[0] and "without its folder" in reported[1],
          f"the checker reports the made-up tree's include that goes up and its bare include, and "
          f"nothing else: {reported}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", required=True)
    args = parser.parse_args()
    self_test()
    src = os.path.join(args.source, "grader", "src")
    allowed, _ = allowed_folders(src)
    order = floors(allowed)
    problems = all_problems(src)
    check(not problems, "grader/src/: every include goes sideways or down the floors "
          f"{' > '.join('/'.join(floor) for floor in order or [])}"
          + "".join(f"\n    {p}" for p in problems))
    return exit_code()


if __name__ == "__main__":
    sys.exit(main())
