#!/usr/bin/env python3
"""The Gradescope autograder (`make gradescope`), ctest label `gradescope`.

Usage: gradescope_test.py --source KIT [--keep]

Gradescope, simulated: autograder.zip is unpacked into a scratch folder's autograder/source, which
a bubblewrap sandbox shows as /autograder (the system read-only, no network, running as root as
Gradescope's harness does). There setup.sh builds the grader, and run_autograder grades three
submissions, each check printing PASS/FAIL (the script exits non-zero if any failed):
- correct (the solutions): every test passed, full marks;
- broken (branching.cpp does not compile, uniform.cpp is the stub, the other labs missing):
  score 0; branching's tests say it does not compile and quote the compiler, uniform's say it
  renders direct light only, the others that they were not submitted;
- correct again, in a container without bubblewrap: results.json is still written, score 0,
  saying why.
Every results.json must follow Gradescope's specification: a numeric score, and tests that each
have a name, a score within 0..max_score, a status of passed or failed, an output and a
visibility.

The grader inside run_autograder makes sandboxes of its own, as an unprivileged user when it
finds itself root: the outer sandbox therefore shows the host's /proc (a nested sandbox may mount
a proc of its own only where the one above it is not partly covered, as bwrap's own --proc is)
and leaves user namespaces enabled.

setup.sh installs packages with scripts/install-deps.sh, which asks apt-get only for packages
that are missing; here `apt-get` is a stand-in that records its arguments and fails, so a
machine that lacks a package says which instead of installing it. The rubric is the kit's with 4
seeds, 2 timed runs and a lenient speed threshold, written over grader/rubric.json of the
unpacked autograder as an instructor would edit it: this test checks how the autograder is put
together, not the grader's statistics or this machine's timings.
"""
import importlib.machinery
import importlib.util
import json
import math
import os
import re
import shutil
import stat
import subprocess
import sys
import tempfile
import time
import zipfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import LABS, check, exit_code, failures, package_test_arguments  # noqa: E402

args = package_test_arguments()
KIT = args.source
CHECKS = ("correctness", "noise", "speed")

# Gradescope's results.json (gradescope-autograders.readthedocs.io, "Autograder Specifications").
RESULT_KEYS = {"score", "execution_time", "output", "output_format", "test_output_format",
               "test_name_format", "visibility", "stdout_visibility", "extra_data", "tests",
               "leaderboard"}
TEST_KEYS = {"score", "max_score", "status", "name", "name_format", "number", "output",
             "output_format", "tags", "visibility", "extra_data"}
VISIBILITIES = {"hidden", "after_due_date", "after_published", "visible"}



def tail(text, lines=30):
    return "\n".join(text.strip().splitlines()[-lines:])


def number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def unzip(archive, folder):
    """Unpacks like unzip(1): Unix permissions kept. Checks where Gradescope needs what."""
    with zipfile.ZipFile(archive) as z:
        names = z.namelist()
        for required in ("setup.sh", "run_autograder", "CMakeLists.txt", "solutions/branching.cpp",
                         "grader/rubric.json", "scripts/install-deps.sh", "framework/lab_list.txt"):
            check(required in names, f"autograder.zip holds {required} at its root")
        check(not any(n.startswith((".git/", "build/", "build-")) for n in names),
              "autograder.zip holds no history and no build folder")
        for info in z.infolist():
            path = z.extract(info, folder)
            mode = info.external_attr >> 16
            if mode and not info.is_dir():
                os.chmod(path, stat.S_IMODE(mode))
        for script in ("setup.sh", "run_autograder"):
            mode = z.getinfo(script).external_attr >> 16
            check(mode & 0o111, f"{script} is executable in the zip")


def system_binds():
    """The host's system, read-only, as the grader's own sandbox shows it."""
    binds = ["--ro-bind", "/usr", "/usr", "--ro-bind", "/etc", "/etc",
             "--ro-bind-try", "/var/lib/dpkg", "/var/lib/dpkg"]
    for top in ("/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"):
        if os.path.islink(top):
            binds += ["--symlink", os.readlink(top), top]
        elif os.path.isdir(top):
            binds += ["--ro-bind", top, top]
    return binds


def in_gradescope(scratch, command, log, extra=()):
    """Runs command in the simulated Gradescope container; returns (exit status, output)."""
    stand_ins = os.path.join(scratch, "stand-ins")
    sandbox = ["bwrap", *system_binds(),
               "--bind", "/proc", "/proc", "--dev", "/dev", "--perms", "1777", "--tmpfs", "/tmp",
               "--bind", os.path.join(scratch, "autograder"), "/autograder",
               "--ro-bind", stand_ins, "/stand-ins", *extra,
               "--unshare-net", "--unshare-ipc", "--unshare-uts", "--die-with-parent",
               "--clearenv", "--setenv", "PATH", "/stand-ins:/usr/local/bin:/usr/bin:/bin",
               "--setenv", "HOME", "/tmp", "--setenv", "LANG", "C.UTF-8",
               "--setenv", "APT_GET_LOG", "/tmp/apt-get.log", "--chdir", "/autograder", *command]
    start = time.monotonic()
    result = subprocess.run(sandbox, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            errors="replace")
    with open(log, "w") as f:
        f.write(result.stdout)
    print(f"  {' '.join(command)}: exit status {result.returncode}, "
          f"{time.monotonic() - start:.0f} s (log: {log})", flush=True)
    return result.returncode, result.stdout


def write_stand_ins(scratch):
    folder = os.path.join(scratch, "stand-ins")
    os.makedirs(folder)
    apt = os.path.join(folder, "apt-get")
    with open(apt, "w") as f:
        f.write('#!/bin/sh\necho "apt-get (stand-in of gradescope_test.py): this machine lacks '
                'packages; asked for: $*" >&2\nexit 1\n')
    os.chmod(apt, 0o755)


def lenient_rubric(source):
    path = os.path.join(source, "grader", "rubric.json")
    with open(path) as f:
        rubric = json.load(f)
    rubric["correctness"]["seeds"] = 4
    rubric["speed"].update({"runs": 2, "min_ratio": 0.25})
    # The instructor's late policy and leaderboard: run_autograder applies the one to the times
    # in submission_metadata.json, results.json carries the other.
    rubric["late"] = {"penalty_per_day": 0.1, "slip_days": 1, "max_penalty": 0.5}
    rubric["gradescope"] = {"leaderboard": True}
    with open(path, "w") as f:
        json.dump(rubric, f, indent=2)
    return rubric


def submit(scratch, files):
    """Empties /autograder/submission and results/, then puts files {name: text} there."""
    for folder in ("submission", "results"):
        path = os.path.join(scratch, "autograder", folder)
        shutil.rmtree(path, ignore_errors=True)
        os.makedirs(path)
    for name, text in files.items():
        with open(os.path.join(scratch, "autograder", "submission", name), "w") as f:
            f.write(text)


def read_results(scratch, what):
    path = os.path.join(scratch, "autograder", "results", "results.json")
    check(os.path.isfile(path), f"{what}: run_autograder wrote results/results.json")
    if not os.path.isfile(path):
        return None
    with open(path) as f:
        results = json.load(f)
    check_specification(results, what)
    return results


def check_specification(results, what):
    problems = []
    if not isinstance(results, dict):
        problems.append("not an object")
        results = {}
    problems += [f"unknown field {k}" for k in results if k not in RESULT_KEYS]
    if not number(results.get("score")):
        problems.append(f"score {results.get('score')!r} is not a number")
    if "execution_time" in results and not isinstance(results["execution_time"], int):
        problems.append("execution_time is not a whole number of seconds")
    if "output" in results and not isinstance(results["output"], str):
        problems.append("output is not text")
    tests = results.get("tests", [])
    if not isinstance(tests, list):
        problems.append("tests is not a list")
        tests = []
    for t in tests:
        name = t.get("name") if isinstance(t, dict) else None
        if not isinstance(name, str):
            problems.append(f"a test without a name: {t!r}")
            continue
        problems += [f"{name}: unknown field {k}" for k in t if k not in TEST_KEYS]
        if not (number(t.get("score")) and number(t.get("max_score")) and
                0 <= t["score"] <= t["max_score"]):
            problems.append(f"{name}: score {t.get('score')!r} of {t.get('max_score')!r}")
        if t.get("status") not in ("passed", "failed"):
            problems.append(f"{name}: status {t.get('status')!r}")
        if not isinstance(t.get("output"), str):
            problems.append(f"{name}: output is not text")
        if t.get("visibility", "visible") not in VISIBILITIES:
            problems.append(f"{name}: visibility {t.get('visibility')!r}")
    if tests and number(results.get("score")) and all(number(t.get("score")) for t in tests):
        total = sum(t["score"] for t in tests)
        # A late submission's score is the tests' sum less the penalty its output states (the
        # top-level score is the one Gradescope takes).
        late = re.search(r"the score loses ([\d.]+)%", str(results.get("output", "")))
        expected = total * (1 - float(late.group(1)) / 100) if late else total
        if abs(expected - results["score"]) > 1e-6:
            problems.append(f"score {results['score']} is not the sum of the tests' {total}"
                            + (f" less the stated {late.group(1)}%" if late else ""))
    check(not problems, f"{what}: results.json follows Gradescope's specification {problems}")


def tests_of(results, lab):
    return {t["name"].split(": ", 1)[1]: t for t in results.get("tests", [])
            if t.get("name", "").startswith(lab + ": ")}


def read(path):
    with open(path) as f:
        return f.read()


def grade_correct(scratch, logs):
    submit(scratch, {f"{lab}.cpp": read(os.path.join(KIT, "solutions", f"{lab}.cpp"))
                     for lab in LABS})
    # Handed in 3 days late (Gradescope's times, in its format): one slip day, then 10% a day.
    metadata = os.path.join(scratch, "autograder", "submission_metadata.json")
    with open(metadata, "w") as f:
        json.dump({"created_at": "2026-12-04T21:00:00.000000-08:00",
                   "assignment": {"due_date": "2026-12-01T23:59:00.000000-08:00"},
                   "users": [{"email": "ada@example.edu", "sid": "s42", "name": "Ada"}]}, f)
    status, output = in_gradescope(scratch, ["/autograder/run_autograder"],
                                   os.path.join(logs, "run_autograder-correct.log"))
    check(status == 0, "correct submission: run_autograder exits 0" +
          ("" if status == 0 else ":\n" + tail(output)))
    results = read_results(scratch, "correct submission")
    if results is None:
        return None
    tests = results.get("tests", [])
    names = sorted(t.get("name") for t in tests)
    # With no hidden scene packed, setup.sh made variants of the public scenes, which a test per
    # lab reports (of no points of its own).
    check(names == sorted([f"{lab}: {c}" for lab in LABS for c in CHECKS]
                          + [f"{lab}: hidden scenes" for lab in LABS]),
          f"correct submission: a test per lab and check, and the hidden scenes' ({len(tests)}: {names})")
    failed = [f"{t.get('name')}: {t.get('output')}" for t in tests if t.get("status") != "passed"]
    check(not failed, f"correct submission: every test passed {failed}")
    full = sum(t.get("max_score", 0) for t in tests)
    check(full > 0 and math.isclose(results.get("score", -1), 0.8 * full)
          and "late: 3 day(s) after the deadline, 1 slip day(s) forgiven: the score loses 20%"
          in results.get("output", ""),
          f"correct submission, 3 days late: full marks less the late policy's 20%, "
          f"{results.get('score')} of {full}, and the output says why")
    board = {entry.get("name"): entry.get("value") for entry in results.get("leaderboard", [])}
    check(board.get("total") == results.get("score") and all(board.get(f"{lab}: efficiency / reference", 0) > 0 for lab in LABS),
          f"the leaderboard: the total (after the late penalty) and each lab's efficiency over the "
          f"reference's ({board})")
    os.remove(metadata)
    return results


def grade_broken(scratch, logs):
    broken = read(os.path.join(KIT, "labs", "branching.cpp")).replace(
        "return radiance;", "return radiance // a missing semicolon")
    submit(scratch, {"branching.cpp": broken,
                     "uniform.cpp": read(os.path.join(KIT, "labs", "uniform.cpp"))})
    status, output = in_gradescope(scratch, ["/autograder/run_autograder"],
                                   os.path.join(logs, "run_autograder-broken.log"))
    check(status == 0, "broken submission: run_autograder exits 0")
    results = read_results(scratch, "broken submission")
    if results is None:
        return None
    check(results.get("score") == 0, f"broken submission: score 0 ({results.get('score')})")
    expected = {"branching": "does not compile", "uniform": "direct light only",
                "importance": "not submitted", "roulette": "not submitted"}
    for lab, words in expected.items():
        tests = tests_of(results, lab)
        correctness = tests.get("correctness", {})
        check(tests and all(t.get("score") == 0 and t.get("status") == "failed"
                            for t in tests.values()),
              f"broken submission: {lab} scores 0 in each check")
        check(words in correctness.get("output", ""),
              f"broken submission: {lab} correctness says '{words}': "
              f"{correctness.get('output', '')[:300]!r}")
    branching = tests_of(results, "branching").get("correctness", {}).get("output", "")
    check("error" in branching and "branching.cpp" in branching,
          "broken submission: branching's output quotes the compiler's error")
    return results


def grade_without_sandbox(scratch, logs):
    submit(scratch, {f"{lab}.cpp": read(os.path.join(KIT, "solutions", f"{lab}.cpp"))
                     for lab in LABS})
    status, _ = in_gradescope(scratch, ["/autograder/run_autograder"],
                              os.path.join(logs, "run_autograder-no-sandbox.log"),
                              extra=("--ro-bind", "/dev/null", "/usr/bin/bwrap"))
    check(status == 0, "without bubblewrap: run_autograder exits 0")
    results = read_results(scratch, "without bubblewrap")
    if results is None:
        return None
    output = results.get("output", "")
    check(results.get("score") == 0 and "could not grade" in output and "bubblewrap" in output,
          f"without bubblewrap: score 0, saying why: {output[:300]!r}")
    return results


def check_student_id(scratch):
    """run_autograder names the submission by the submitter's id from submission_metadata.json
    (the per-student variants' seed), as a plain folder name, and "submission" without one."""
    loader = importlib.machinery.SourceFileLoader(
        "run_autograder", os.path.join(KIT, "scripts", "gradescope", "run_autograder"))
    module = importlib.util.module_from_spec(importlib.util.spec_from_loader(loader.name, loader))
    loader.exec_module(module)
    metadata = os.path.join(scratch, "submission_metadata.json")
    found = []
    for users in ([{"sid": "s123", "email": "a@uni.edu"}], [{"email": "../a b@uni.edu"}], []):
        with open(metadata, "w") as f:
            json.dump({"users": users}, f)
        found.append(module.student_id(metadata))
    found.append(module.student_id(os.path.join(scratch, "none.json")))
    check(found == ["s123", "submission.._a_b_uni.edu", "submission", "submission"],
          f"run_autograder names a submission by its sid, else its email, spelled as the grader "
          f"spells ids: {found}")


def main():
    start = time.monotonic()
    scratch = tempfile.mkdtemp(prefix="pathlab-gradescope-test-")
    check_student_id(scratch)
    logs = os.path.join(scratch, "logs")
    os.makedirs(logs)
    # Gradescope's /autograder belongs to root and is open to all; mkdtemp's folder is not.
    os.chmod(scratch, 0o755)
    summary = {}
    try:
        archive = os.path.join(scratch, "autograder.zip")
        env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
        made = subprocess.run(["make", "gradescope", f"BUILD={scratch}"], cwd=KIT, env=env,
                              capture_output=True, text=True)
        check(made.returncode == 0 and os.path.isfile(archive),
              f"make gradescope writes autograder.zip: {made.stdout.strip()} {made.stderr.strip()}")
        if failures:
            return 1
        source = os.path.join(scratch, "autograder", "source")
        unzip(archive, source)
        write_stand_ins(scratch)

        began = time.monotonic()
        status, output = in_gradescope(scratch, ["bash", "/autograder/source/setup.sh"],
                                       os.path.join(logs, "setup.log"))
        summary["setup.sh seconds"] = round(time.monotonic() - began)
        check(status == 0, "setup.sh installs nothing here and builds the grader" +
              ("" if status == 0 else ":\n" + tail(output)))
        if status != 0:
            return 1
        # Gradescope copies run_autograder there when it builds the image.
        shutil.copy2(os.path.join(source, "run_autograder"),
                     os.path.join(scratch, "autograder", "run_autograder"))
        lenient_rubric(source)

        for name, grading in (("correct", grade_correct), ("broken", grade_broken),
                              ("no sandbox", grade_without_sandbox)):
            began = time.monotonic()
            results = grading(scratch, logs)
            summary[f"{name}: seconds"] = round(time.monotonic() - began)
            if results is not None:
                summary[f"{name}: score"] = results.get("score")
                summary[f"{name}: max"] = sum(t.get("max_score", 0)
                                              for t in results.get("tests", []))
    finally:
        if args.keep:
            print(f"kept {scratch}")
        else:
            shutil.rmtree(scratch, ignore_errors=True)
    print(f"gradescope test: {json.dumps(summary)}")
    return exit_code("gradescope test: ", time.monotonic() - start)


if __name__ == "__main__":
    sys.exit(main())
