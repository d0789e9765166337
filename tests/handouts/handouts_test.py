#!/usr/bin/env python3
"""The handouts and the students' README: they render, link only to what exists, quote only
commands that run, and the handouts explain every step of the lab stubs.

Usage: handouts_test.py --build BUILD --source SOURCE

The students' README is README-student.md in the instructor's kit and README.md in the student
release (which has no solutions/): this test runs in both, so what they claim is checked where
students read it.

Checks, each printing PASS/FAIL (the script exits non-zero if any failed):
- every handouts/*.md renders to HTML with pandoc (handouts/tools/make_html.py), without a
  warning, its formulas as MathML and its figures embedded;
- every link and image of a handout or the README names a file that exists, and every #anchor a
  heading of the page it points to; every kit path quoted in `code` exists;
- every generated block (make handouts) holds numbers;
- every command quoted in a ```sh block, and every `./viewer`, `./grader`, `make` or `ctest`
  command quoted inline, runs: viewer renders at 16x16 pixels and 1 spp into a scratch folder,
  grader options must appear in `grader --help`, make targets must exist (`make -n`), ctest
  selections must select tests (`ctest -N`), scripts must exist and be executable;
- every TODO(labN.M) of labs/*.cpp has a section of that name in the handout the lab file names,
  in the same order, and every labN.M section of a handout is a TODO of labs/.
Needs no display.
"""
import argparse
import glob
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import check, exit_code  # noqa: E402




FENCE = re.compile(r"^```(\w*)\n(.*?)^```", re.M | re.S)
INLINE_CODE = re.compile(r"`([^`\n]+)`")
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
KIT_FOLDERS = ("labs/", "solutions/", "framework/", "models/", "handouts/", "grader/", "tests/",
               "scripts/", "apps/", "docs/")


def prose(markdown):
    """The text outside fenced and inline code, where links are."""
    return INLINE_CODE.sub("", FENCE.sub("", markdown))


def read(path):
    with open(path) as f:
        return f.read()


def check_rendering(source, handouts, pages):
    tools = os.path.join(source, "handouts", "tools")
    run = subprocess.run([sys.executable, os.path.join(tools, "make_html.py"), "--out", pages],
                         capture_output=True, text=True)
    check(run.returncode == 0 and not run.stderr.strip(),
          f"make_html.py renders every handout without warnings {run.stderr.strip()}")
    for path in handouts:
        name = os.path.basename(path)
        page = os.path.join(pages, name[:-3] + ".html")
        if not os.path.exists(page):
            check(False, f"{name}: rendered to {os.path.basename(page)}")
            continue
        html = read(page)
        markdown = read(path)
        if "$" in prose(markdown):
            check("<math" in html and "$$" not in html, f"{name}: formulas rendered as MathML")
        images = re.findall(r"<img [^>]*src=\"([^\"]*)\"", html)
        check(all(src.startswith("data:") for src in images),
              f"{name}: its {len(images)} images are embedded in the page")


def anchors(pages, name):
    path = os.path.join(pages, os.path.basename(name)[:-3] + ".html")
    return set(re.findall(r"id=\"([^\"]+)\"", read(path))) if os.path.exists(path) else set()


def check_links(source, documents, pages):
    for path in documents:
        folder = os.path.dirname(path)
        name = os.path.basename(path)
        markdown = read(path)
        bad = []
        for target in LINK.findall(prose(markdown)):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target):
                continue  # an absolute URL
            file, _, anchor = target.partition("#")
            if file and not os.path.exists(os.path.join(folder, file)):
                bad.append(target)
            elif anchor and anchor not in anchors(pages, file or name):
                bad.append(target)
        check(not bad, f"{name}: every link and image exists {bad or ''}")
        quoted = [c for c in INLINE_CODE.findall(FENCE.sub("", markdown))
                  if c.startswith(KIT_FOLDERS) and " " not in c and "*" not in c]
        missing = [c for c in quoted if not os.path.exists(os.path.join(source, c))]
        check(not missing, f"{name}: the {len(quoted)} kit paths it quotes exist {missing or ''}")
        blocks = re.findall(r"<!-- BEGIN generated: ([\w-]+) -->\n(.*?)<!-- END generated: \1 -->",
                            markdown, re.S)
        empty = [b for b, text in blocks if not re.search(r"\d", text)]
        check(not empty, f"{name}: its generated blocks hold numbers (make handouts) {empty or ''}")


class CommandRunner:
    """Runs quoted commands the cheap way, from the source or the build folder as a student
    would (`cd build` moves there)."""

    OUTPUT_OPTIONS = {"-o", "--stats", "--screenshot", "--capture-window"}

    def __init__(self, source, build, scratch):
        self.source, self.build, self.scratch = source, build, scratch
        self.cwd = source
        self.written = set()
        self.grader_help = None

    def run(self, line):
        """Returns (ok, detail) for one command line."""
        words = shlex.split(line, comments=True)
        if not words:
            return True, ""
        program, args = words[0], words[1:]
        if program == "cd":
            target = args[0] if args else ""
            self.cwd = self.build if target in ("build", "build/") else \
                self.source if target == ".." and self.cwd == self.build else \
                self.source if target == "pathlab" else None  # the release's folder
            return self.cwd is not None, f"cd {target}"
        if program == "make":
            return self.make(args)
        if program == "./viewer":
            return self.viewer(args)
        if program == "./grader":
            return self.grader(args)
        if program == "ctest":
            return self.ctest(args)
        if program in ("python3", "python"):
            return self.python(args)
        if program == "tar":
            # How the student release is unpacked: tests/release/ checks the tarball's layout.
            return args[:1] == ["xzf"] and args[1:] == ["pathlab-student.tar.gz"], "tar xzf"
        if program.startswith("scripts/"):
            path = os.path.join(self.source, program)
            return os.access(path, os.X_OK), f"{program} is executable"
        if program == "xvfb-run":
            # The window under a virtual display: xvfb-run is installed (make deps installs it),
            # and the command it runs passes its own rule.
            inner = [a for a in args if a != "-a"]
            if not shutil.which("xvfb-run"):
                return False, "xvfb-run is not installed"
            return self.run(shlex.join(inner))
        return False, f"no rule to check {program!r}"

    def make(self, args):
        """The target exists: `make -n` prints its recipe (a folder of the same name would
        otherwise pass as an up-to-date target)."""
        run = subprocess.run(["make", "-n", *args], cwd=self.source, capture_output=True,
                             text=True)
        ok = run.returncode == 0 and run.stdout.strip() and "Nothing to be done" not in run.stdout
        return bool(ok), run.stderr.strip() or run.stdout.strip().splitlines()[-1:]

    def viewer(self, args):
        if "--help" not in args:
            args = self.tiny(args)
        run = subprocess.run([os.path.join(self.build, "viewer"), *args], cwd=self.build,
                             capture_output=True, text=True, timeout=60,
                             env={k: v for k, v in os.environ.items() if k != "DISPLAY"})
        return run.returncode == 0, run.stderr.strip().splitlines()[-1:] if run.returncode else ""

    def tiny(self, args):
        """The same render at 16x16 pixels and 1 spp, writing into the scratch folder."""
        out, i = [], 0
        while i < len(args):
            a = args[i]
            if a in self.OUTPUT_OPTIONS and i + 1 < len(args):
                self.written.add(args[i + 1])
                out += [a, os.path.join(self.scratch, os.path.basename(args[i + 1]))]
                i += 2
            elif a == "--reference" and i + 1 < len(args) and args[i + 1] in self.written:
                out += [a, os.path.join(self.scratch, os.path.basename(args[i + 1]))]
                i += 2
            elif a in ("--spp", "--frames") and i + 1 < len(args):
                out += [a, "1"]
                i += 2
            elif a == "--size" and i + 2 < len(args):
                i += 3
            else:
                out.append(a)
                i += 1
        if "-o" not in out:  # a window command: the same options, headless
            out += ["-o", os.path.join(self.scratch, "window.pfm")]
        if "--spp" not in out:
            out += ["--spp", "1"]
        return out + ["--size", "16", "16"]

    def grader(self, args):
        if self.grader_help is None:
            run = subprocess.run([os.path.join(self.build, "grader"), "--help"],
                                 capture_output=True, text=True, timeout=60)
            self.grader_help = run.stdout + run.stderr if run.returncode == 0 else ""
        if not self.grader_help:
            return False, "grader --help failed"
        unknown = [a for a in args if (a.startswith("-") or a == "make-references")
                   and not re.search(rf"(^|\s){re.escape(a)}\b", self.grader_help, re.M)]
        return not unknown, f"not in grader --help: {unknown}" if unknown else ""

    def ctest(self, args):
        run = subprocess.run(["ctest", "-N", *args], cwd=self.build, capture_output=True,
                             text=True, timeout=60)
        total = re.search(r"Total Tests: (\d+)", run.stdout)
        return run.returncode == 0 and total and int(total.group(1)) > 0, \
            f"selects {total.group(1) if total else 'no'} tests"

    def python(self, args):
        script = os.path.join(self.source, args[0]) if args else ""
        run = subprocess.run([sys.executable, script, "--help"], capture_output=True, text=True)
        return run.returncode == 0, run.stderr.strip()


INLINE_COMMAND = re.compile(r"^(\./viewer|\./grader|make|ctest) ")


def check_commands(source, build, documents, scratch):
    for path in documents:
        name = os.path.basename(path)
        markdown = read(path)
        runner = CommandRunner(source, build, scratch)
        count = 0
        for language, body in FENCE.findall(markdown):
            if language != "sh":
                continue
            runner.cwd = source
            for line in body.splitlines():
                if not line.split("#")[0].strip():
                    continue
                ok, detail = runner.run(line)
                count += 1
                check(ok, f"{name}: runs `{line.strip()}` {detail or ''}")
        for code in INLINE_CODE.findall(FENCE.sub("", markdown)):
            if not INLINE_COMMAND.match(code):
                continue
            runner.cwd = build if code.startswith("./") else source
            ok, detail = runner.run(code)
            count += 1
            check(ok, f"{name}: runs `{code}` {detail or ''}")
        check(count > 0 or name == "notation.md", f"{name}: quotes {count} commands")


def lab_number(step):
    major, minor = step[3:].split(".")
    return int(major), int(minor)


def check_todos(source, handouts):
    """The stubs' TODO steps against the handouts' sections. In the student release labs/ holds
    the student's own work, whose TODO markers go as the labs get written: there this check would
    fail a finished lab, so it runs in the kit only (where labs/ are the stubs as shipped)."""
    if not os.path.isdir(os.path.join(source, "solutions")):
        print("skipped: the TODO steps of labs/ against the handouts (the student release: "
              "labs/ is your own work; the kit checks its stubs)", flush=True)
        return
    sections = {}
    for path in handouts:
        steps = re.findall(r"^#{2,4} (lab\d+\.\d+)\b", read(path), re.M)
        sections[os.path.basename(path)] = steps
    documented = {s for steps in sections.values() for s in steps}
    in_labs = set()
    for lab in sorted(glob.glob(os.path.join(source, "labs", "*.cpp"))):
        text = read(lab)
        name = "labs/" + os.path.basename(lab)
        comments = re.findall(r"TODO\((lab\d+\.\d+)\)", text)
        markers = re.findall(r"PATHLAB_TODO\(\"(lab\d+\.\d+)\"[,)]", text)
        check(comments == markers and comments,
              f"{name}: its TODO comments and PATHLAB_TODO markers agree {comments} {markers}")
        handout = re.search(r"Handout: handouts/([\w.-]+\.md)", text)
        check(handout and handout.group(1) in sections,
              f"{name}: names its handout ({handout.group(1) if handout else 'none'})")
        if not handout or handout.group(1) not in sections:
            continue
        steps = sections[handout.group(1)]
        check(steps == sorted(comments, key=lab_number) and steps == comments,
              f"{name}: each TODO has a section of the same name in {handout.group(1)}, in order "
              f"(sections {steps}, TODOs {comments})")
        in_labs.update(comments)
    stray = sorted(documented - in_labs)
    check(not stray, f"every labN.M section of the handouts is a TODO in labs/ {stray or ''}")


def section(markdown, heading):
    """The text under `heading` (a line such as "## Grading") up to the next heading of its level."""
    level = heading.split(" ")[0]
    start = markdown.find("\n" + heading + "\n")
    if start < 0:
        return ""
    end = markdown.find("\n" + level + " ", start + len(heading) + 2)
    return markdown[start:end if end >= 0 else len(markdown)]


def check_rubric_numbers(source, readme):
    """The grading sections students read quote none of the rubric's numbers, which an instructor
    may change: they point to `grader rubric`, which prints them from the rubric itself."""
    rubric = json.load(open(os.path.join(source, "grader", "rubric.json")))
    c, check_ = rubric["correctness"], rubric["parameter_check"]
    quoted = {
        f"{c['width']}×{c['height']}", f"{c['tiles']}×{c['tiles']}", f"{c['seeds']} seeds",
        f"{c['seeds']} renders", f"maxDepth` {rubric['parameters']['max_depth']}",
        f"maxDepth {rubric['parameters']['max_depth']}", f"continueProb {rubric['parameters']['continue_prob']}",
        f"continueProb` {rubric['parameters']['continue_prob']}", f"({check_['max_depth']})",
        f"({check_['continue_prob']})", f"limit is {rubric['noise']['max_ratio']}",
        f"{rubric['speed']['min_ratio']} times", f"at least {rubric['speed']['min_ratio']}",
    }
    for path, heading in ((readme, "## Grading"), (os.path.join(source, "handouts", "00-setup.md"),
                                                  "## Tests and the grader")):
        text = section(read(path), heading)
        found = sorted(q for q in quoted if q in text)
        check(text and "grader rubric" in text and not found,
              f"{os.path.basename(path)}, {heading}: points to `grader rubric` and quotes no rubric number"
              + (f" (quotes {found})" if found else ""))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", required=True)
    parser.add_argument("--source", required=True)
    args = parser.parse_args()
    source, build = os.path.abspath(args.source), os.path.abspath(args.build)
    handouts = sorted(glob.glob(os.path.join(source, "handouts", "*.md")))
    check(len(handouts) >= 6, f"handouts/ has its handouts ({len(handouts)} files)")
    in_release = not os.path.isdir(os.path.join(source, "solutions"))
    readme = os.path.join(source, "README.md" if in_release else "README-student.md")
    check("make run" in read(readme) and "pathlab-student.tar.gz" in read(readme),
          f"{os.path.relpath(readme, source)} is the students' README")
    with tempfile.TemporaryDirectory() as tmp:
        pages, scratch = os.path.join(tmp, "pages"), os.path.join(tmp, "scratch")
        os.makedirs(scratch)
        check_rendering(source, handouts, pages)
        check_links(source, handouts + [readme], pages)
        check_commands(source, build, handouts + [readme], scratch)
    check_todos(source, handouts)
    check_rubric_numbers(source, readme)
    return exit_code()


if __name__ == "__main__":
    sys.exit(main())
