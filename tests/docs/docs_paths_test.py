#!/usr/bin/env python3
"""The maintainers' and instructors' documents name only files that exist, ctest `docs`.

Usage: docs_paths_test.py --source KIT [DOCUMENT.md ...]
(default: README.md and every docs/*.md; none of them is in the student release)

What counts as a repository path, in `code` or as a markdown link's target:
- a token with a slash whose first folder is one of the kit's (labs/, framework/, grader/, ...,
  .ci/): it must exist, relative to the kit's root (a link: relative to the document's folder);
- an include path, pathlab/NAME.h (or runner/NAME.h, process/NAME.h, the layers that name their
  headers after their folder): it must exist in some FOLDER/include/ of the kit (runner/ and
  process/ paths may also be relative to the kit's root);
- a bare file name with a source extension (.cpp, .h, .py, .sh, ...): some file of the kit must
  have that name (the text around it says which folder);
- a word in capitals (NAME, LAB, PLATFORM_test.py) or a * stands for any name: at least one
  file must match;
- `path:FUNCTION` (or `path:Class::function`) must exist and hold the function's last name;
  `path#anchor`, for a markdown file, must have a heading of that anchor.
Not paths: tokens with a space (commands), URLs, absolute paths (/proc/self/exe), and what the
root .gitignore keeps out of the tree (build/, third_party/: made by the build or by hand), and
UNTRACKED below.

Before the documents, a made-up one checks that the checker itself reports a missing file, a
missing function, a missing anchor, an include path and a pattern that match nothing.
Prints PASS/FAIL per document; exits non-zero if any failed.
"""
import argparse
import fnmatch
import glob
import os
import re
import sys

# Folders the kit's documents name that git does not track, and why.
UNTRACKED = {
    "grader/hidden_scenes/": "the instructor's hidden scenes, made by hand, never committed",
}
# The kit's top-level folders: a slash token starting with one of them is a path of the kit.
KIT_FOLDERS = {".ci", "apps", "cmake", "docs", "framework", "grader", "handouts", "labs", "models",
               "process", "runner", "scripts", "solutions", "tests"}
# The first folders of include paths (#include "pathlab/lab.h", "runner/lab_tables.h"): such a
# path is looked for in every FOLDER/include/ of the kit too.
INCLUDE_FOLDERS = {"pathlab", "runner", "process"}
SOURCE_EXTENSIONS = (".cpp", ".h", ".py", ".sh", ".cmake", ".gp", ".lua", ".sbatch")

FENCE = re.compile(r"^```.*?^```", re.M | re.S)
INLINE_CODE = re.compile(r"`([^`\n]+)`")
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
PLACEHOLDER = re.compile(r"(?<![A-Za-z0-9])[A-Z][A-Z0-9]*(?![A-Za-z0-9])")


def ignored_by_git(source, path):
    """Whether the root .gitignore keeps `path`'s first folder out of the tree (/build/, ...)."""
    gitignore = os.path.join(source, ".gitignore")
    if not os.path.exists(gitignore):
        return False
    first = path.split("/")[0]
    for line in open(gitignore):
        pattern = line.strip()
        if pattern.startswith("/") and pattern.endswith("/") and \
                fnmatch.fnmatch(first, pattern.strip("/")):
            return True
    return False


def as_pattern(path):
    """The path with its placeholders (words in capitals: NAME, LAB, NN in NN-NAME.md, PLATFORM
    in PLATFORM_test.py) as *. README is a name, not a placeholder."""
    return PLACEHOLDER.sub(lambda m: m.group(0) if m.group(0) == "README" else "*", path)


def matches(base, path):
    """The files or folders under `base` that `path` (placeholders and * allowed) names."""
    pattern = as_pattern(path)
    if "*" not in pattern:
        return [os.path.join(base, pattern)] if os.path.exists(os.path.join(base, pattern)) else []
    return glob.glob(os.path.join(base, pattern))


def heading_anchors(markdown):
    """GitHub's anchors of a markdown file's headings."""
    anchors = set()
    for heading in re.findall(r"^#+\s+(.*?)\s*$", markdown, re.M):
        slug = re.sub(r"[^\w\- ]", "", heading.lower().replace("`", "")).replace(" ", "-")
        anchors.add(slug)
    return anchors


class Tree:
    def __init__(self, source):
        self.source = source
        self.names = {}
        for folder, subfolders, files in os.walk(source):
            subfolders[:] = [s for s in subfolders if s != ".git" and not (
                folder == source and ignored_by_git(source, s + "/"))]
            for f in files:
                self.names.setdefault(f, []).append(os.path.join(folder, f))
        self.include_dirs = sorted(glob.glob(os.path.join(source, "*", "include")))

    def problem(self, token, folder):
        """Why `token` (named in a document in `folder`) is not a file of the kit, or None; also
        None for a token that is no repository path."""
        token = token.strip().rstrip(".,;")
        link = folder is not None
        if not token or " " in token or re.match(r"^[a-z][a-z0-9+.-]*:", token) or \
                token.startswith(("/", "~", "$", "-")):
            return None  # a command, a URL, an absolute path or an option
        path, _, anchor = token.partition("#")
        path, _, function = path.partition(":")
        if link:
            path = os.path.normpath(os.path.join(folder, path)) if path else None
            if path is None:
                return None
            if path.startswith(".."):
                return f"{token}: outside the kit"
        if "/" not in path.rstrip("/"):
            if path.endswith(SOURCE_EXTENSIONS) and not link:
                found = self.names.get(path) or \
                    [f for name, fs in self.names.items() if fnmatch.fnmatch(name, as_pattern(path))
                     for f in fs]
                return None if found else f"{token}: no file of the kit has that name"
            if not link:
                return None
        first = path.split("/")[0]
        include = first in INCLUDE_FOLDERS
        if not (link or include or first in KIT_FOLDERS):
            return None  # a folder the kit makes elsewhere (OUT/, submissions/ID/)
        if ignored_by_git(self.source, path) or any(path.startswith(u) for u in UNTRACKED):
            return None
        bases = self.include_dirs + ([self.source] if first in KIT_FOLDERS else []) if include \
            else [self.source]
        found = [f for base in bases for f in matches(base, path)]
        if not found:
            return f"{token}: no such file"
        if function:
            name = re.split(r"::|\.", function)[-1].rstrip("()")
            if not any(os.path.isfile(f) and re.search(rf"\b{re.escape(name)}\b", open(f).read())
                       for f in found):
                return f"{token}: {name} is not in {path}"
        if anchor and path.endswith(".md"):
            if not any(anchor in heading_anchors(open(f).read()) for f in found if os.path.isfile(f)):
                return f"{token}: no heading #{anchor} in {path}"
        return None

    def problems(self, markdown, document_folder):
        outside_fences = FENCE.sub("", markdown)
        found = [self.problem(code, None) for code in INLINE_CODE.findall(outside_fences)]
        prose = INLINE_CODE.sub("", outside_fences)
        found += [self.problem(target, document_folder) for target in LINK.findall(prose)]
        return sorted({p for p in found if p})


# A document that names one file of each kind that exists and one of each that does not: the
# checker must report exactly the latter.
SELF_TEST = """
`framework/src/render/renderer.cpp:Renderer::renderPass`, `pathlab/lab.h`, `labs/NAME.cpp`,
`renderer.cpp`, `docs/instructor-guide.md`, `grader/src/checks/*_check.cpp`, `make test`,
`build/viewer`, [the kit](../README.md#quick-start), `/proc/self/exe`, `grader/hidden_scenes/`,
`OUT/.canary/`, `runner/lab_tables.h`, `process/child_process.h`, `runner/src/lab_table.cpp`.
`framework/src/no_such_renderer.cpp`, `framework/src/render/renderer.cpp:noSuchFunction`,
`pathlab/no_such_header.h`, `labs/NAME.hpp`, `no_such_file.cpp`, [a link](no_such_page.md),
[an anchor](../README.md#no-such-heading), `tests/no_such_folder/`, `runner/no_such_table.h`.
"""
SELF_TEST_MISSING = 9


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--source", required=True)
    parser.add_argument("documents", nargs="*")
    args = parser.parse_args()
    source = os.path.abspath(args.source)
    tree = Tree(source)
    failures = 0

    reported = tree.problems(SELF_TEST, "docs")
    ok = len(reported) == SELF_TEST_MISSING and all(re.search(r"no[_-]?such|\.hpp", p, re.I) for p in reported)
    print(f"{'PASS' if ok else 'FAIL'} the checker reports the {SELF_TEST_MISSING} made-up paths "
          f"of its own test document and nothing else: {reported}", flush=True)
    failures += not ok

    documents = args.documents or [os.path.join(source, "README.md")] + \
        sorted(glob.glob(os.path.join(source, "docs", "*.md")))
    for path in documents:
        relative = os.path.relpath(os.path.abspath(path), source)
        reported = tree.problems(open(path).read(), os.path.dirname(relative))
        print(f"{'FAIL' if reported else 'PASS'} {relative}: every repository path it names "
              f"exists" + "".join(f"\n    {p}" for p in reported), flush=True)
        failures += bool(reported)
    print(f"{failures} failed" if failures else "all passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
