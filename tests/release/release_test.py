#!/usr/bin/env python3
"""The student release (`make student-release`), ctest label `release`.

Usage: release_test.py --source KIT [--keep]

Checks, each printing PASS/FAIL (the script exits non-zero if any failed):
1. The tarball unpacks into one folder, pathlab/, with the framework (and the list of labs,
   framework/lab_list.txt, from which the release's CMake generates pathlab/lab_list.h, as the
   kit's does), the stubs of labs/ as they are, the models, the grader with its rubric and references, the handouts and scripts, and the
   students' README (README-student.md) as its README.md; and without solutions/, .git, the
   grader's mutant and hostile labs or the tests built on them, the instructors' documents,
   archives or compiled code, or any scene but the kit's public ones in models/ (no hidden ones).
2. No solution code in any file: every line of solutions/*.cpp that is code (comments dropped),
   longer than 25 characters and not also a line of a stub (the stubs share the skeleton: the
   include, the signature, the steps given to the student) is searched for, whitespace
   normalised, in every text file of the release. The same search finds them in the kit's
   mutants (solutions with one bug), so it can fail.
3. The packaging's exclusions, on a made-up kit without git: only its public files are taken.
4. Unpacked, the release works as a student's first commands expect, without a display: `make
   run` (install check, configure, the first build, then a headless render of the student's lab
   1) exits 0, names the image it wrote, which exists, and lists lab 1's steps still to write.
   "It passes its own tests, the stubs failing as expected" means: `make test` (ctest without
   the labels `slow` and `labs`) succeeds and ran the framework's tests and the handouts' (which
   check the students' README and handouts from the release); `make test-labs` (ctest -L labs:
   each lab's furnace, NaN and reference tests, run on the student's own labs/) fails, each of
   estimators.lab1 to estimators.lab4 among the failures; `make grade LAB=branching` fails the stub with the
   diagnosis "direct light only" and a note that speed is not checked without the solutions;
   once labs/branching.cpp is done (the solution copied in), estimators.lab1 passes while the
   other labs' tests still fail; and with every lab done, `make grade` passes with the speed
   points shown apart and prints the speed ratios between labs beside the reference's, `make
   sweep LAB=roulette` plots the student's lab 4, a lab 2 that traces black components is told
   its speed points are at risk and why, and `make report` writes lab-report.md with
   every figure filled in and that plot shown.
5. The targets that need the solutions say so in one line and exit non-zero (`make bench`).
"""
import glob
import json
import os
import re
import shutil
import subprocess
import sys
import tarfile
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import LABS, check, exit_code, failures, package_test_arguments  # noqa: E402

args = package_test_arguments()
KIT = args.source
SHORTEST_FINGERPRINT = 26  # characters, whitespace normalised



def normalised(text):
    return " ".join(text.split())


def read_text(path):
    """A file's text, or None for a binary file."""
    try:
        with open(path, encoding="utf-8") as f:
            return f.read()
    except UnicodeDecodeError:
        return None


def code_lines(path):
    """The lines of a C++ file without their comments, whitespace normalised."""
    lines = []
    for line in read_text(path).splitlines():
        line = normalised(line.split("//")[0])
        if line:
            lines.append(line)
    return lines


def fingerprints(stubs):
    """{solution file: its distinctive lines}."""
    skeleton = {line for stub in stubs for line in code_lines(stub)}
    return {path: [line for line in code_lines(path)
                   if len(line) >= SHORTEST_FINGERPRINT and line not in skeleton]
            for path in sorted(glob.glob(os.path.join(KIT, "solutions", "*.cpp")))}


def text_files(root):
    """{path relative to root: whitespace-normalised text} of every text file under root."""
    texts = {}
    for folder, _, files in os.walk(root):
        for name in files:
            path = os.path.join(folder, name)
            text = read_text(path)
            if text is not None:
                texts[os.path.relpath(path, root)] = normalised(text)
    return texts


def run(command, cwd, log, env=None):
    """Runs a command, its output to log; returns (exit status, output, seconds)."""
    # A make above this test (make test) must not hand its job server or level to this one.
    env = {k: v for k, v in (env or os.environ).items()
           if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    start = time.monotonic()
    result = subprocess.run(command, cwd=cwd, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, errors="replace")
    seconds = time.monotonic() - start
    with open(log, "w") as f:
        f.write(result.stdout)
    print(f"  {' '.join(command)}: exit status {result.returncode}, {seconds:.0f} s "
          f"(log: {log})", flush=True)
    return result.returncode, result.stdout, seconds


def tail(text, lines=40):
    return "\n".join(text.strip().splitlines()[-lines:])


def ctest_results(output):
    """{test name: 'Passed' | 'Failed' | ...} from ctest's progress lines."""
    results = {}
    for match in re.finditer(r"Test\s+#\d+: (\S+) \.+\**\s*(\w+)", output):
        results[match.group(1)] = match.group(2)
    return results


def check_contents(root, files):
    def present(path):
        return path in files

    for lab in LABS:
        stub = os.path.join("labs", lab + ".cpp")
        with open(os.path.join(KIT, stub), "rb") as kit:
            with open(os.path.join(root, stub), "rb") as out:
                check(kit.read() == out.read(), f"{stub} is the kit's stub, unchanged")
    with open(os.path.join(KIT, "README-student.md"), "rb") as kit:
        with open(os.path.join(root, "README.md"), "rb") as out:
            check(kit.read() == out.read(), "README.md is the students' README (README-student.md)")
    for path in ("README.md", "Makefile", "CMakeLists.txt", "framework/include/pathlab/lab.h",
                 "framework/lab_list.txt", "cmake/lab_list.cmake", "cmake/lab_list.h.in",
                 "apps/viewer/main.cpp", "grader/rubric.json", "scripts/install-deps.sh",
                 "handouts/01-branching.md", "models/cornell_box_VI2_Specular.ecs",
                 "tests/support/test_support.cpp", "tests/estimators/furnace_test.cpp",
                 "tests/handouts/handouts_test.py", "handouts/tools/make_html.py",
                 "grader/references/lab_figures.json", "scripts/run-default-scene.sh",
                 "scripts/sweep.py", "scripts/sweep.gp", "tests/sweep/sweep_test.py",
                 "handouts/figures/roulette_sweep.csv", "handouts/figures/depth_sweep.csv"):
        check(present(path), f"the release holds {path}")
    references = {os.path.relpath(p, KIT)
                  for p in glob.glob(os.path.join(KIT, "grader", "references", "*"))}
    check(references and references <= files, f"the release holds grader/references/ "
                                              f"({len(references)} files)")

    def any_named(test):
        return sorted(f for f in files if test(f))[:5]

    for what, found in (
            ("solutions/", any_named(lambda f: "solutions/" in f)),
            ("history (.git)", any_named(lambda f: ".git/" in f or f.endswith(".git"))),
            ("mutant or hostile labs", any_named(lambda f: "/mutants" in f or "/hostile/" in f)),
            ("grader tests built on them",
             any_named(lambda f: f in ("tests/grader/grader_test.py",
                                       "tests/grader/batch_test.py",
                                       "tests/grader/pages_test.py",
                                       "tests/grader/instructor_test.py",
                                       "tests/grader/support.py"))),
            ("kit's test on Debian 13", any_named(lambda f: f.startswith("tests/platforms/"))),
            ("instructors' or maintainers' documents, their test, or the kit's README",
             any_named(lambda f: f.startswith(("docs/", "tests/docs/")) or f == "README-student.md")),
            ("archives or compiled code",
             any_named(lambda f: f.endswith((".zip", ".tar", ".gz", ".tgz", ".o", ".a", ".so")))),
            ("scenes outside models/ (hidden ones)",
             any_named(lambda f: f.endswith(".ecs") and not f.startswith("models/")))):
        check(not found, f"the release has no {what} {found if found else ''}")
    public = {os.path.relpath(p, KIT) for p in glob.glob(os.path.join(KIT, "models", "*"))}
    extra = sorted(f for f in files if f.startswith("models/") and f not in public)
    check(not extra, f"models/ holds only the kit's public scenes {extra if extra else ''}")
    binary = sorted(f for f in files if read_text(os.path.join(root, f)) is None and
                    not f.endswith((".exr", ".png")))
    check(not binary, f"every binary file is an image {binary if binary else ''}")


def check_no_solution_code(root):
    prints = fingerprints(glob.glob(os.path.join(root, "labs", "*.cpp")))
    for path, lines in prints.items():
        check(len(lines) >= 4, f"{os.path.relpath(path, KIT)}: {len(lines)} distinctive lines "
                               "to search for")
    texts = text_files(root)
    leaks = [(os.path.relpath(path, KIT), line, name)
             for path, lines in prints.items() for line in lines
             for name, text in texts.items() if line in text]
    for solution, line, name in leaks[:10]:
        print(f"  {name} holds this line of {solution}: {line}")
    check(not leaks, f"no line of solutions/*.cpp in the release's {len(texts)} text files "
                     f"({sum(map(len, prints.values()))} lines searched)")
    mutants = text_files(os.path.join(KIT, "tests", "grader", "mutants"))
    found = {line for lines in prints.values() for line in lines
             if any(line in text for text in mutants.values())}
    check(len(found) > len(prints) * 3, f"the search finds solution lines where they are: "
                                        f"{len(found)} of them in the kit's mutants")


def check_exclusions(scratch):
    sys.path.insert(0, os.path.join(KIT, "scripts"))
    import package_kit

    fake = os.path.join(scratch, "fake-kit")
    for path in ("labs/branching.cpp", "solutions/branching.cpp", "models/box.ecs",
                 "grader/hidden_scenes/exam.ecs", "tests/grader/mutants/bug/branching.cpp",
                 "tests/grader/hostile/bomb/branching.cpp", "tests/grader/grader_test.py",
                 "tests/sampling/random_test.cpp", "build/viewer", "build-release/viewer"):
        os.makedirs(os.path.dirname(os.path.join(fake, path)), exist_ok=True)
        open(os.path.join(fake, path), "w").close()
    for path in ("README.md", "README-student.md", "docs/instructor-guide.md"):
        os.makedirs(os.path.dirname(os.path.join(fake, path)), exist_ok=True)
        with open(os.path.join(fake, path), "w") as f:
            f.write(path)
    taken = package_kit.student_files(fake)
    check(taken == {"README.md": "README-student.md", "labs/branching.cpp": "labs/branching.cpp",
                    "models/box.ecs": "models/box.ecs",
                    "tests/sampling/random_test.cpp": "tests/sampling/random_test.cpp"},
          f"on a made-up kit without git, the release takes only the public files, the "
          f"students' README as its README: {taken}")


def without_display():
    return {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}


def check_first_run(root, logs):
    status, output, seconds = run(["make", "run"], root, os.path.join(logs, "make-run.log"),
                                  without_display())
    image = re.search(r"make run: the image is (\S+)", output)
    check(status == 0 and image and os.path.isfile(image.group(1)),
          f"make run without a display exits 0 and writes the image it names, in {seconds:.0f} s "
          f"with the first build" + ("" if status == 0 else ":\n" + tail(output)))
    check("labs/branching.cpp has steps still to write: lab1.1 lab1.2 lab1.3 lab1.4 lab1.5" in output,
          "make run lists lab 1's steps still to write")
    check("is not done yet" not in output, "make run sums the TODO warnings up in that one line")


def check_builds_and_tests(root, logs):
    status, output, _ = run(["make", "test"], root, os.path.join(logs, "make-test.log"))
    results = ctest_results(output)
    check(status == 0, "make test succeeds in the release" + ("" if status == 0 else
                                                              ":\n" + tail(output)))
    framework = ("sampling", "scene", "render", "grader", "handouts", "sweep")
    check(all(results.get(t) == "Passed" for t in framework),
          f"make test ran the framework's and the handouts' tests, which pass: {results}")
    check(not any(name.startswith("estimators") for name in results),
          "make test leaves the lab tests to make test-labs")

    status, output, _ = run(["make", "test-labs"], root, os.path.join(logs, "make-test-labs.log"))
    results = ctest_results(output)
    check(status != 0, "make test-labs fails with the stubs")
    check(all(results.get(f"estimators.lab{n}") == "Failed" for n in range(1, 5)),
          f"each lab's tests fail with its stub: {results}")

    status, output, _ = run(["make", "grade", "LAB=branching"], root,
                            os.path.join(logs, "make-grade.log"))
    check(status != 0 and "direct light only" in output,
          "make grade fails the branching stub: direct light only" +
          ("" if "direct light only" in output else ":\n" + tail(output)))
    check("speed is not checked" in output, "make grade says speed is not checked")

    status, output, _ = run(["make", "bench"], root, os.path.join(logs, "make-bench.log"))
    check(status != 0 and "needs the reference solutions" in output,
          f"make bench says it needs the solutions: {output.strip()[-120:]!r}")

    # A student who finishes lab 1 (here: with its solution) passes lab 1's tests.
    shutil.copy(os.path.join(KIT, "solutions", "branching.cpp"), os.path.join(root, "labs"))
    status, output, _ = run(["make", "test-labs"], root,
                            os.path.join(logs, "make-test-labs-lab1-done.log"))
    results = ctest_results(output)
    check(results.get("estimators.lab1") == "Passed" and
          all(results.get(f"estimators.lab{n}") == "Failed" for n in range(2, len(LABS) + 1)),
          f"with lab 1 done, its tests pass and the others still fail: {results}")


def check_finished_labs(root, logs):
    """All the labs done (the solutions copied in): the local grade and the lab report."""
    for lab in LABS:
        shutil.copy(os.path.join(KIT, "solutions", lab + ".cpp"), os.path.join(root, "labs"))
    status, output, _ = run(["make", "grade"], root, os.path.join(logs, "make-grade-done.log"))
    # The kit's rubric's points: correctness and noise graded here, speed by the instructor.
    points = json.load(open(os.path.join(KIT, "grader", "rubric.json")))["points"]
    here = sum(p["correctness"] + p["noise"] for p in points.values())
    speed = sum(p["speed"] for p in points.values())
    total = f"total {here}/{here} (+{speed} speed: graded by the instructor)"
    check(status == 0 and total in output,
          f"make grade passes every lab and shows the speed points apart: {total!r}" +
          ("" if status == 0 and total in output else ":\n" + tail(output)))
    others = "|".join(LABS[1:])
    ratios = re.findall(rf"^  ({others})/branching\s+(\d+\.\d+)\s+(\d+\.\d+)$", output, re.M)
    check(len(ratios) == len(LABS) - 1, f"make grade prints the speed ratios between labs, yours "
                                         f"and the reference's: {ratios}")
    # The README: the kit's own tests pass from the start, and still once the labs are written.
    status, output, _ = run(["make", "test"], root, os.path.join(logs, "make-test-done.log"))
    check(status == 0, "make test still passes with every lab done" +
          ("" if status == 0 else ":\n" + tail(output)))
    status, output, _ = run(["./grader", "submission", "../labs", "--out", "graded"],
                            os.path.join(root, "build"), os.path.join(logs, "grader-submission.log"))
    check(status == 2 and "is the instructor's" in output,
          f"grader submission says it is the instructor's: {output.strip()[-160:]!r}")
    # The student's own experiment, small, so that the report below has a plot to show.
    status, output, _ = run(["make", "sweep", "LAB=roulette", "VALUES=0.3 0.8", "SIZE=32",
                             "SPP=4"], root, os.path.join(logs, "make-sweep.log"))
    plot = os.path.join(root, "build", "sweep", "roulette-continue-prob", "sweep.png")
    check(status == 0 and os.path.isfile(plot) and "the figures are in" in output,
          "make sweep LAB=roulette renders the student's lab 4 and plots it" +
          ("" if status == 0 else ":\n" + tail(output)))
    status, output, _ = run(["make", "report"], root, os.path.join(logs, "make-report.log"))
    report_path = os.path.join(root, "lab-report.md")
    report = open(report_path).read() if os.path.exists(report_path) else ""
    check(status == 0 and report, "make report writes lab-report.md")
    rows = [line for line in report.splitlines() if line.startswith("| ") and "---" not in line]
    empty = [line for line in rows if re.search(r"\|\s*(–|-|not measured[^|]*)?\s*\|", line)]
    check(len(rows) >= 5 + 5 + 4 and not empty,
          f"every figure of lab-report.md is filled in ({len(rows)} table rows): {empty[:3]}")
    check("grader/references/lab_figures.json" in report and "cores" in report,
          "the report names the machine the reference's figures were measured on")
    check("](build/sweep/roulette-continue-prob/sweep.png)" in report,
          "the report shows the plot of make sweep")
    check("samples per CPU-second ÷ lab 1's" in report,
          "the report's ratios between labs are of samples per CPU-second")

    # A lab 2 that traces the ray of a picked component even where it is black: the same image,
    # more bounce rays. Without the solutions to time it against, make grade still says its
    # speed points are at risk, and why (the instructor's grader fails its speed).
    shutil.copy(os.path.join(KIT, "tests", "grader", "mutants", "uniform_traces_black",
                             "uniform.cpp"), os.path.join(root, "labs"))
    status, output, _ = run(["make", "grade", "LAB=uniform"], root,
                            os.path.join(logs, "make-grade-traces-black.log"))
    check(status == 0 and "8/8 (+2 speed: graded by the instructor; 2 of them at risk)" in output
          and "the bounce rays of the lab's estimator" in output
          and "a black component traced?" in output,
          "make grade tells a lab 2 that traces black components that its speed points are at "
          "risk, and why" + ("" if status == 0 else ":\n" + tail(output)))
    shutil.copy(os.path.join(KIT, "solutions", "uniform.cpp"), os.path.join(root, "labs"))


def main():
    start = time.monotonic()
    scratch = tempfile.mkdtemp(prefix="pathlab-release-test-")
    logs = os.path.join(scratch, "logs")
    os.makedirs(logs)
    try:
        status, output, seconds = run(["make", "student-release", f"BUILD={scratch}"], KIT,
                                      os.path.join(logs, "make-student-release.log"))
        tarball = os.path.join(scratch, "pathlab-student.tar.gz")
        check(status == 0 and os.path.isfile(tarball),
              f"make student-release writes {os.path.basename(tarball)}: {output.strip()}")
        if failures:
            return 1
        with tarfile.open(tarball) as tar:
            members = tar.getmembers()
            names = [m.name for m in members]
            check(all(n.startswith("pathlab/") and ".." not in n.split("/") for n in names),
                  "every file of the tarball is under pathlab/")
            check(all(m.isfile() for m in members), "the tarball holds only plain files")
            unpacked = os.path.join(scratch, "unpacked")
            if hasattr(tarfile, "data_filter"):
                tar.extractall(unpacked, filter="data")
            else:
                tar.extractall(unpacked)
        root = os.path.join(unpacked, "pathlab")
        files = {n[len("pathlab/"):] for n in names}
        print(f"  {len(files)} files, {os.path.getsize(tarball) / 1e6:.1f} MB", flush=True)

        check_contents(root, files)
        check_no_solution_code(root)
        check_exclusions(scratch)
        check_first_run(root, logs)
        check_builds_and_tests(root, logs)
        check_finished_labs(root, logs)
    finally:
        if args.keep:
            print(f"kept {scratch}")
        else:
            shutil.rmtree(scratch, ignore_errors=True)
    return exit_code("release test: ", time.monotonic() - start)


if __name__ == "__main__":
    sys.exit(main())
