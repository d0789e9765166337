#!/usr/bin/env python3
"""A fifth lab needs its line in the lab list and its files, nothing else: ctest `docs.fifth_lab`.

Usage: fifth_lab_test.py --source KIT [--keep]

framework/lab_list.txt is the one place the labs are counted (docs/architecture.md: Adding a
lab). This test copies the kit, adds a lab `fifth` to the copy's list (the next lab, unbiased), gives
it a stub and a reference solution (lab 4's, renamed: its steps are labN.1, ... for its number N), and builds the copy
with warnings as errors, so that a switch over the labs that misses one stops the build. Nothing
else of the copy is edited, except the rubric: a lab's points and samples per pixel are the
instructor's to give, so the test's rubric gives them, and the kit's rubric, which has none for
the new lab, must be refused with words that name it.

Then the new lab is rendered, inspected, reported and graded:
- its solution renders the very image lab 4's solution renders (it is the same code), and the
  viewer's --help names it;
- the inspector replays it and names its steps labN.M, from the lab's place in the list;
- the lab report's figures have its rows, labelled by its number;
- the grader grades it: its solution passes correctness, its stub fails, and the words name
  its step (TODO labN.2); the grader's --help names its file, and a submission's fifth.cpp is
  taken at intake.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import LABS, check, exit_code, package_test_arguments  # noqa: E402

# The added lab comes after the kit's own: its number, and the kit's last lab before it.
N = len(LABS) + 1
LAST = LABS[-1]

SCENE = "models/cornell_box_VI2_Specular.ecs"
SMALL = ["--size", "64", "64", "--continue-prob", "0.8", "--seed", "7", "--threads", "2"]


def copy_kit(source, kit):
    """The kit's files, as git sees them (tracked, and new ones it does not ignore), into `kit`;
    all of them, less its builds, where the kit is not a git clone."""
    listed = subprocess.run(["git", "-C", source, "ls-files", "-z", "--cached", "--others",
                             "--exclude-standard"], capture_output=True)
    if listed.returncode == 0 and listed.stdout:
        for name in listed.stdout.decode().split("\0"):
            if name and os.path.isfile(os.path.join(source, name)):
                os.makedirs(os.path.join(kit, os.path.dirname(name)), exist_ok=True)
                shutil.copy2(os.path.join(source, name), os.path.join(kit, name))
    else:
        shutil.copytree(source, kit, ignore=shutil.ignore_patterns("build*", ".git"))


def add_fifth_lab(kit):
    """The line and the two files: lab 4's stub and solution under the name `fifth`."""
    with open(os.path.join(kit, "framework", "lab_list.txt"), "a", encoding="utf-8") as f:
        f.write("fifth         Fifth         unbiased\n")
    for folder in ("labs", "solutions"):
        with open(os.path.join(kit, folder, "roulette.cpp"), encoding="utf-8") as f:
            text = f.read()
        text = text.replace("pathlab::roulette", "pathlab::fifth").replace("lab4.", f"lab{N}.")
        with open(os.path.join(kit, folder, "fifth.cpp"), "w", encoding="utf-8") as f:
            f.write(text)


def run(command, cwd, timeout=600):
    result = subprocess.run(command, cwd=cwd, capture_output=True, text=True, timeout=timeout)
    return result.returncode, result.stdout + result.stderr


def build(kit):
    """Configured as CI configures the kit, warnings as errors; the programs the checks run.
    Optimised at -O1, not the release's -O3: a third less compile time, and this test times
    nothing (its renders are small, its grading takes no speed); every image it compares is made
    by this one build."""
    status, output = run(["cmake", "-S", ".", "-B", "build", "-G", "Ninja",
                          "-DCMAKE_BUILD_TYPE=Release", "-DPATHLAB_RELEASE_OPTIMIZATION=-O1",
                          "-DPATHLAB_WARNINGS_AS_ERRORS=ON"], kit)
    if status == 0:
        status, output = run(["cmake", "--build", "build", "--target", "viewer", "grader",
                              "viewer_solutions_as_student", "pathlab-sandbox-init"], kit,
                             timeout=1500)
    check(status == 0, "the copy with a fifth lab builds with warnings as errors" +
          ("" if status == 0 else ":\n" + output[-3000:]))
    return status == 0


def rubric_with_fifth(kit, path):
    """The kit's rubric, quick (the furnace alone, 4 seeds), with lab 4's points and spp for the
    fifth lab."""
    with open(os.path.join(kit, "grader", "rubric.json"), encoding="utf-8") as f:
        rubric = json.load(f)
    rubric["points"]["fifth"] = dict(rubric["points"]["roulette"])
    rubric["correctness"]["spp"]["fifth"] = rubric["correctness"]["spp"]["roulette"]
    rubric["correctness"]["scenes"] = ["furnace"]
    rubric["speed"]["scene"] = rubric["noise"]["scene"] = "furnace"
    rubric["correctness"]["seeds"] = 4
    rubric["limits"]["seconds_per_run"] = 20
    with open(path, "w", encoding="utf-8") as f:
        json.dump(rubric, f, indent=1)


def check_render_and_inspect(build_dir, scratch):
    status, helped = run(["./viewer", "--help"], build_dir)
    check(f"| {LAST} | fifth" in helped, "the viewer's --help names the fifth lab")
    images = {}
    for lab in ("roulette", "fifth"):
        image = os.path.join(scratch, lab + ".pfm")
        status, output = run(["./viewer", "-c", SCENE, "--lab", lab, "--solution", "--spp", "8",
                              "-o", image] + SMALL, build_dir)
        check(status == 0, f"--lab {lab} --solution renders" + ("" if status == 0 else output))
        images[lab] = open(image, "rb").read() if status == 0 else b""
    check(images["fifth"] and images["fifth"] == images["roulette"],
          "the fifth lab's solution renders lab 4's image bit for bit (it is lab 4's code)")

    replay = os.path.join(scratch, "replay.json")
    status, output = run(["./viewer", "-c", SCENE, "--lab", "fifth", "--inspect", "30", "40",
                          "--inspect-out", replay] + SMALL, build_dir)
    check(status == 0, "the inspector replays the fifth lab" + ("" if status == 0 else output))
    if status == 0:
        written = json.load(open(replay))
        check(written["lab"] == "fifth" and written["uses_roulette"],
              f"its JSON names the lab and reports roulette draws: {written['lab']!r}, "
              f"{written['uses_roulette']!r}")
        summary = (written.get("comparison") or {}).get("summary", "")
        check(f"lab{N}.2" in summary and "lab4." not in summary,
              f"the stub's paths are compared with the solution's by its own steps: {summary!r}")


def check_grading(build_dir, scratch, kit):
    rubric = os.path.join(scratch, "rubric.json")
    rubric_with_fifth(kit, rubric)
    status, output = run(["./grader", "--help"], build_dir)
    check(f"{LAST}.cpp, fifth.cpp" in output and f"| {LAST} | fifth" in output,
          "the grader's --help names the fifth lab and its file")

    status, output = run(["./grader", "--lab", "fifth", "--no-speed"], build_dir)
    says = f'points has no entry for the lab "fifth" (lab {N})'
    check(status == 2 and says in output,
          f"the kit's rubric, with no points for the fifth lab, is refused: \"{says}\"" +
          ("" if says in output else f"; it said: {output.strip()[-400:]}"))

    results = {}
    for who, viewer in (("solution", "viewer_solutions_as_student"), ("stub", "viewer")):
        report = os.path.join(scratch, who + ".json")
        # The lab report (its notebook's figures take a minute) of the solution alone.
        lab_report = ["--report", os.path.join(scratch, "solution.md")] if who == "solution" else []
        status, output = run(["./grader", "--viewer", viewer, "--lab", "fifth", "--no-speed",
                              "--rubric", rubric, "--threads", "2", "--json", report] +
                             lab_report, build_dir, timeout=900)
        results[who] = (status, output, json.load(open(report)) if os.path.exists(report) else {})
    status, output, graded = results["solution"]
    labs = graded.get("labs", [])
    check(status == 0 and [lab.get("lab") for lab in labs] == ["fifth"],
          "the fifth lab's solution is graded and passes" +
          ("" if status == 0 else ":\n" + output[-2000:]))
    status, output, graded = results["stub"]
    todo = f"TODO lab{N}.2"
    check(status == 1 and todo in output,
          f"the fifth lab's stub fails, the words naming its step {todo}" +
          ("" if status == 1 and todo in output else ":\n" + output[-2000:]))
    report = open(os.path.join(scratch, "solution.md"), encoding="utf-8").read() \
        if os.path.exists(os.path.join(scratch, "solution.md")) else ""
    check(f"fifth, continueProb 0.1 (lab {N}'s default)" in report,
          "the lab report's figures label the fifth lab by its number")


def check_intake(kit, scratch):
    """The unpacker takes the files the grader names, the fifth lab's among them."""
    submission = os.path.join(scratch, "submission", "labs")
    os.makedirs(submission)
    for name in ("roulette.cpp", "fifth.cpp"):
        shutil.copy(os.path.join(kit, "labs", name), submission)
    out = os.path.join(scratch, "intake")
    os.makedirs(out)
    status, output = run([sys.executable, os.path.join(kit, "grader", "sandbox",
                                                       "unpack_submission.py"),
                          os.path.dirname(submission), "262144", "roulette.cpp", "fifth.cpp"],
                         out)
    taken = json.load(open(os.path.join(out, "intake.json")))["taken"] if status == 0 else {}
    check(sorted(taken) == ["fifth.cpp", "roulette.cpp"],
          f"intake takes the lab files the grader names, fifth.cpp too: {sorted(taken)}")


def main():
    args = package_test_arguments()
    start = time.monotonic()
    scratch = tempfile.mkdtemp(prefix="pathlab-fifth-lab-")
    try:
        kit = os.path.join(scratch, "kit")
        copy_kit(args.source, kit)
        add_fifth_lab(kit)
        check_intake(kit, scratch)
        if build(kit):
            build_dir = os.path.join(kit, "build")
            check_render_and_inspect(build_dir, scratch)
            check_grading(build_dir, scratch, kit)
    finally:
        if args.keep:
            print("kept", scratch)
        else:
            shutil.rmtree(scratch, ignore_errors=True)
    return exit_code(seconds=time.monotonic() - start)


if __name__ == "__main__":
    sys.exit(main())
