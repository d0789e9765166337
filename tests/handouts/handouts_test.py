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
  in the same order, and every labN.M section of a handout is a TODO of labs/;
- the figures of handouts/figures/ are by CPU time: every row of roulette_sweep.csv,
  depth_sweep.csv, convergence.csv and estimators.csv has its samples per CPU-second (and the
  wall clock's figures beside them), and its efficiency is 1/(relative MSE × CPU seconds), within
  the CSV's rounding; `make sweep` and `make convergence` read them as the handout's rows
  (scripts/sweep.py, scripts/convergence.py); and, in the kit (make_figures.py is not in the
  release), each generated block of the handouts is what make_figures.py makes of those numbers.
Needs no display.
"""
import argparse
import csv
import glob
import importlib
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


def close(a, b, relative=3e-3, absolute=1e-4):
    """Equal within the CSVs' rounding: 4 significant digits, or 4 decimals for efficiencies."""
    return abs(a - b) <= max(relative * max(abs(a), abs(b)), absolute)


def csv_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def positive(row, *columns):
    try:
        return all(float(row[c]) > 0 for c in columns)
    except (KeyError, TypeError, ValueError):
        return False


def check_figure_tables(source):
    """The CSVs of handouts/figures/: figures by CPU time, the wall clock's beside them, and
    efficiency per CPU-second, each row consistent with itself."""
    figures = os.path.join(source, "handouts", "figures")
    sweep = csv_rows(os.path.join(figures, "roulette_sweep.csv"))
    check(sweep and all(positive(r, "samples_per_cpu_second", "cpu_seconds", "seconds",
                                 "samples_per_second") for r in sweep),
          f"roulette_sweep.csv: samples per CPU-second and CPU seconds in every row ({len(sweep)})")
    off = [(r["continue_prob"], r["efficiency"]) for r in sweep if positive(r, "cpu_seconds") and
           not close(float(r["efficiency"]),
                     1 / (float(r["relative_rmse"]) ** 2 * float(r["cpu_seconds"])))]
    check(sweep and not off,
          f"roulette_sweep.csv: efficiency is 1/(relative MSE × CPU seconds) {off[:3] or ''}")
    depth = csv_rows(os.path.join(figures, "depth_sweep.csv"))
    off = [(r["lab"], r["max_depth"]) for r in depth if not positive(r, "cpu_seconds", "noise") or
           not close(float(r["efficiency"]), 1 / (float(r["noise"]) ** 2 * float(r["cpu_seconds"])))]
    check(depth and all(positive(r, "samples_per_cpu_second", "samples_per_second") for r in depth)
          and not off,
          f"depth_sweep.csv: samples per CPU-second, and efficiency 1/(noise² × CPU seconds), in "
          f"every row {off[:3] or ''}")
    convergence = csv_rows(os.path.join(figures, "convergence.csv"))
    off = [(r["estimator"], r["spp"]) for r in convergence
           if not positive(r, "cpu_seconds", "seconds", "samples_per_cpu_second", "relative_rmse")
           or not close(float(r["efficiency"]),
                        1 / (float(r["relative_rmse"]) ** 2 * float(r["cpu_seconds"])))]
    check(convergence and not off,
          f"convergence.csv: CPU and wall seconds, samples per CPU-second, and efficiency "
          f"1/(relative MSE × CPU seconds) in every row {off[:3] or ''}")
    with open(os.path.join(figures, "run.json")) as f:
        window = json.load(f)["parameters"]["window_size"]
    estimators = csv_rows(os.path.join(figures, "estimators.csv"))
    off = [r["estimator"] for r in estimators
           if not positive(r, "samples_per_cpu_second", "window_samples_per_cpu_second", "noise",
                           "frame_rate", "efficiency_wall")
           or not close(float(r["efficiency"]), float(r["window_samples_per_cpu_second"]) /
                        (float(r["noise"]) ** 2 * float(r["noise_spp"]) * window * window))]
    check(estimators and not off,
          f"estimators.csv: the window's frame rate and samples per CPU-second, and efficiency "
          f"per CPU-second, in every row {off or ''}")


def import_script(folder, name):
    """A script of the kit as a module (make sweep's, make convergence's, make_figures.py)."""
    if folder not in sys.path:
        sys.path.insert(0, folder)
    return importlib.import_module(name)


def check_handout_rows(source):
    """make sweep and make convergence draw the handout's figures beside a student's: they read
    handouts/figures/ by CPU time."""
    sweep = import_script(os.path.join(source, "scripts"), "sweep")
    for lab, estimate in sweep.headless_viewer.lab_estimates().items():
        parameter = next(p for p in sweep.PARAMETERS.values() if p.estimate == estimate)
        rows = sweep.handout_rows(sweep.Sweep(lab, parameter, parameter.defaults,
                                              sweep.DEFAULT_SIZE, sweep.DEFAULT_SPP, False))
        check(len(rows) >= 2 and all(positive(r, "samples_per_cpu_second", "efficiency")
                                     for r in rows),
              f"make sweep LAB={lab} reads the handout's {len(rows)} rows of {parameter.label}, "
              "with their samples per CPU-second")
    convergence = import_script(os.path.join(source, "scripts"), "convergence")
    rows = convergence.handout_rows()
    # The labs the handout's convergence figure has a curve of (a later lab has none yet).
    labs = {lab for lab, _, key in convergence.LABS if key}
    check({r["lab"] for r in rows} == labs and
          all(positive(r, "cpu_seconds_256", "samples_per_cpu_second") for r in rows),
          f"make convergence reads the handout's curves of the labs {sorted(labs)} by CPU time "
          f"({len(rows)} rows)")


def check_generated_blocks(source, handouts):
    """Each generated block of the handouts is what make_figures.py makes of handouts/figures/
    (its tables rewritten after the numbers changed). make_figures.py is not in the release."""
    tools = os.path.join(source, "handouts", "tools")
    if not os.path.exists(os.path.join(tools, "make_figures.py")):
        print("skipped: the generated blocks against handouts/figures/ (the student release has "
              "no make_figures.py)", flush=True)
        return
    blocks = import_script(tools, "make_figures").generated_blocks(
        os.path.join(source, "handouts", "figures"))
    for path in handouts:
        found = re.findall(r"<!-- BEGIN generated: ([\w-]+) -->\n(.*?)\n<!-- END generated: \1 -->",
                           read(path), re.S)
        if not found:
            continue
        stale = [name for name, text in found if name in blocks and blocks[name] != text]
        check(not stale, f"{os.path.basename(path)}: its generated blocks are those of "
                         f"handouts/figures/ (make_figures.py --blocks-only) {stale or ''}")


def inspect_solution(source, build, lab, x, y, samples, *extra):
    """The reference solution's inspection of pixel (x, y) of the VI2 box, as JSON."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "inspection.json")
        scene = os.path.join(source, "models", "cornell_box_VI2_Specular.ecs")
        run = subprocess.run([os.path.join(build, "viewer"), "-c", scene, "--lab", lab,
                              "--solution", "--inspect", str(x), str(y),
                              "--inspect-samples", str(samples), "--inspect-out", out, *extra],
                             capture_output=True, text=True, timeout=120,
                             env={k: v for k, v in os.environ.items() if k != "DISPLAY"})
        if run.returncode != 0:
            return None
        return json.load(open(out))


def first_vertices(source, build, lab, x, y):
    inspection = inspect_solution(source, build, lab, x, y, 4)
    return [s["vertices"][0] for s in (inspection or {}).get("samples", [])]


# The pixels the handouts inspect, by the words that say what they show: (document, pattern of
# the pixel, what the text says, whether the reference solution's first vertex shows it). The
# VI2 box's .obj: the back wall is the plane z = 559.2, the floor y = 0, the red wall x = 550
# or so (it leans); the glass sphere is Ks 0.1 Kt 0.9, the floor Kd with a mirror Ks.
NAMED_PIXELS = [
    ("handouts/01-branching.md", r"the glass sphere:\s*```sh\s*make inspect LAB=\w+ X=(\d+) Y=(\d+)",
     "the glass sphere", lambda v: max(v["material"]["Kt"]) > 0),
    ("handouts/01-branching.md", r"back wall \(`X=(\d+) Y=(\d+)`\)", "the back wall, lit",
     lambda v: abs(v["position"][2] - 559.2) < 0.1 and max(v["direct_light"]) > 0),
    ("handouts/02-uniform-pick.md", r"The floor has a diffuse and a mirror component:\s*```sh\s*"
     r"make inspect LAB=\w+ X=(\d+) Y=(\d+)", "the floor, diffuse and mirror",
     lambda v: abs(v["position"][1]) < 0.1 and max(v["material"]["Kd"]) > 0
     and max(v["material"]["Ks"]) > 0),
    ("handouts/03-importance-pick.md", r"The same pixel of the floor as in lab 2[^`]*```sh\s*"
     r"make inspect LAB=\w+ X=(\d+) Y=(\d+)", "the floor, diffuse and mirror",
     lambda v: abs(v["position"][1]) < 0.1 and max(v["material"]["Kd"]) > 0
     and max(v["material"]["Ks"]) > 0),
    ("handouts/04-russian-roulette.md", r"Pixel \((\d+), (\d+)\) of the red wall", "the red wall",
     lambda v: v["position"][0] > 540 and v["material"]["Kd"][0] > 2 * v["material"]["Kd"][1]),
]


def check_inspected_pixels(source, build):
    """What the handouts say of the pixels they inspect holds for the reference solutions (each
    named pixel's first vertex, in every one of 4 samples, is on the surface the text names), and
    handout 4's seeds have a path that survives three bounces at continueProb 0.1 among 256
    samples."""
    if not os.path.isdir(os.path.join(source, "solutions")):
        return  # the student release has no --solution
    for document, pattern, says, shows in NAMED_PIXELS:
        found = re.search(pattern, read(os.path.join(source, document)))
        check(found is not None, f"{document} names a pixel of {says}")
        if not found:
            continue
        x, y = found.groups()
        firsts = first_vertices(source, build, "branching", x, y)
        check(firsts and all(v["found"] and shows(v) for v in firsts),
              f"{document}: pixel ({x}, {y}) shows {says} (first vertex at "
              f"{[[round(c, 1) for c in v['position']] for v in firsts[:1]]}, material "
              f"{firsts[0]['material'] if firsts else None})")
    four = read(os.path.join(source, "handouts", "04-russian-roulette.md"))
    seeds = re.search(r"the reference solution has one at seeds (\d+) and (\d+)", four)
    check(seeds is not None, "handout 4 names the seeds with a path of three bounces")
    for seed in seeds.groups() if seeds else []:
        inspection = inspect_solution(source, build, "roulette", 30, 256, 256, "--continue-prob", "0.1",
                                      "--seed", seed)
        longest = max((len(s["vertices"]) for s in (inspection or {}).get("samples", [])), default=0)
        check(longest >= 4, f"handout 4: at seed {seed}, a path of pixel (30, 256) reaches vertex 3 "
                            f"at continueProb 0.1 (longest: {longest} vertices)")


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
    check_figure_tables(source)
    check_handout_rows(source)
    check_generated_blocks(source, handouts)
    check_inspected_pixels(source, build)
    return exit_code()


if __name__ == "__main__":
    sys.exit(main())
