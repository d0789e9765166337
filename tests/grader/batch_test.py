#!/usr/bin/env python3
"""grader batch on a generated class: correct, buggy and hostile submissions as folders, .zip,
.tar.gz and git repositories. Each must get its intended verdict and reason; every hostile one
must be stopped (the files it tried to write do not exist, the port it tried to reach saw no
connection, no process of it is left); the correct ones score full marks beside them; a batch
run again skips what is done, a batch killed half-way and restarted writes the same gradebook
rows, and the Slurm scripts' shards merge into the same gradebook as one batch.

The hostile lab files live in tests/grader/hostile/; @OUTSIDE@, @SOURCE@ and @PORT@ in them are
filled in here. The rubric is the public one with fewer seeds and smaller timed renders, so that
the test is quick, and a lenient speed threshold; the checks and the sandbox are the same.

With --class-only it grades the class once and checks the verdicts and the sandbox, and leaves
out the run again, the restart and the shards: the batch's bookkeeping, which is Python and C++
of the kit's own and the same on every system (platforms.debian13 runs it so, in its Debian 13
root, where the sandbox is what differs).
"""
import csv
import json
import os
import re
import shutil
import signal
import socket
import subprocess
import tarfile
import tempfile
import threading
import time
import zipfile

from support import LABS, arguments, check, finish, grader, write

args = arguments((["--class-only"], {"action": "store_true",
                                     "help": "grade the class once: no rerun, restart or shards"}))
GRADER = grader(args)
SOLUTIONS = os.path.join(args.source, "solutions")
STUBS = os.path.join(args.source, "labs")
HOSTILE = os.path.join(args.source, "tests", "grader", "hostile")
MUTANTS = os.path.join(args.source, "tests", "grader", "mutants")


def copy_labs(source, folder, labs=LABS):
    os.makedirs(folder, exist_ok=True)
    for lab in labs:
        shutil.copy(os.path.join(source, lab + ".cpp"), folder)


class Listener:
    """A port on the host's loopback that records any connection a submission makes."""

    def __init__(self):
        self.socket = socket.socket()
        self.socket.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        self.socket.bind(("127.0.0.1", 0))
        self.socket.listen(8)
        self.socket.settimeout(0.5)
        self.port = self.socket.getsockname()[1]
        self.connections = 0
        self.running = True
        threading.Thread(target=self.serve, daemon=True).start()

    def serve(self):
        while self.running:
            try:
                connection, _ = self.socket.accept()
                self.connections += 1
                connection.close()
            except socket.timeout:
                pass


# An environment variable of the grader's, as a CI or Gradescope host may hold a token: no
# submission may read it (hostile/proc_snoop), and nothing under OUT may hold it.
SECRET = "pathlab-test-secret-" + os.urandom(8).hex()


def tile_means_table():
    """C++ initialisers of hostile/table_of_tile_means' SceneTable, one per public scene: its
    camera (from its .ecs) and the shipped reference's depth-limited means, whole image then tiles."""
    entries = []
    for scene in ("cornell_box_VI2_Specular", "furnace", "mirror_furnace", "refraction_check", "mixed_surfaces"):
        camera = {}
        for line in open(os.path.join(args.source, "models", scene + ".ecs")):
            words = line.split()
            if words and words[0] in ("-vp", "-vi", "-vu", "-fov"):
                camera[words[0]] = [float(w) for w in words[1:]]
        reference = json.load(open(os.path.join(args.source, "grader", "references", scene + ".json")))
        means = reference["depth_limited"]["mean"]
        rows = ", ".join("{%r, %r, %r}" % tuple(means[3 * r:3 * r + 3]) for r in range(len(means) // 3))
        vector = lambda v: "Vec3(%rf, %rf, %rf)" % tuple(v)
        entries.append("{%s, %s, %s, %rf, %s, %s, %d, {%s}}" % (
            vector(camera["-vp"]), vector(camera["-vi"]), vector(camera["-vu"]), camera["-fov"][0],
            "true" if scene == "mirror_furnace" else "false", "true" if "furnace" in scene else "false",
            reference["max_depth"], rows))
    return ",\n    ".join(entries)


def committed_repository(repository, labs):
    """A git repository of the solutions' `labs`, committed."""
    copy_labs(SOLUTIONS, repository, labs)
    git = ["git", "-C", repository, "-c", "user.name=student", "-c", "user.email=s@example.com"]
    subprocess.run(["git", "init", "-q", repository], check=True)
    subprocess.run(git + ["add", *(lab + ".cpp" for lab in labs)], check=True)
    subprocess.run(git + ["commit", "-q", "-m", "labs"], check=True)


def smudging_repository(repository, outside):
    """A git submission whose own configuration and attributes would run code wherever git
    checks its files out: a smudge filter (whose output would become the lab file), a
    file-system monitor and hooks. The intake reads its blobs without any of them."""
    copy_labs(SOLUTIONS, repository, ["uniform"])
    write(os.path.join(repository, ".gitattributes"), "*.cpp filter=evil\n")
    git = ["git", "-C", repository, "-c", "user.name=student", "-c", "user.email=s@example.com"]
    subprocess.run(["git", "init", "-q", repository], check=True)
    subprocess.run(git + ["add", "uniform.cpp", ".gitattributes"], check=True)
    subprocess.run(git + ["commit", "-q", "-m", "lab 2"], check=True)
    ran = os.path.join(outside, "git-ran")
    hooks = repository + "-hooks"
    for key, value in (("filter.evil.smudge", f"sh -c 'touch {ran}; id; cat /proc/1/environ'; echo SMUDGED"),
                       ("filter.evil.required", "true"),
                       ("core.fsmonitor", f"touch {ran}; echo"),
                       ("core.hooksPath", hooks)):
        subprocess.run(["git", "-C", repository, "config", key, value], check=True)
    write(os.path.join(hooks, "post-checkout"), f"#!/bin/sh\ntouch {ran}\n")
    os.chmod(os.path.join(hooks, "post-checkout"), 0o755)


def make_class(root, outside, port):
    """The submissions, and what each must get: {id: (scores by lab, status words, feedback words)}."""
    subs = os.path.join(root, "submissions")
    expected = {}
    # Correct, in every form a submission takes.
    copy_labs(SOLUTIONS, os.path.join(subs, "correct", "labs"))
    expected["correct"] = ({lab: 10 for lab in LABS}, "graded", "mean radiance matches")
    with zipfile.ZipFile(os.path.join(subs, "correct_zip.zip"), "w") as z:
        # writestr stores permission bits without a file type: a plain file all the same.
        z.writestr("uniform.cpp", open(os.path.join(SOLUTIONS, "uniform.cpp")).read())
    expected["correct_zip"] = ({"uniform": 10}, "graded", "mean radiance matches")
    with tarfile.open(os.path.join(subs, "correct_tar.tar.gz"), "w:gz") as t:
        t.add(os.path.join(SOLUTIONS, "uniform.cpp"), "student7/pathlab/labs/uniform.cpp")
        t.add(os.path.join(STUBS, "uniform.cpp"), "student7/old/uniform.cpp")  # the labs/ copy wins
    expected["correct_tar"] = ({"uniform": 10}, "graded", "mean radiance matches")
    repository = os.path.join(subs, "correct_git")
    committed_repository(repository, ["uniform"])
    write(os.path.join(repository, "uniform.cpp"), "uncommitted, and not C++\n")  # HEAD is graded
    expected["correct_git"] = ({"uniform": 10}, "graded", "mean radiance matches")
    smudging_repository(os.path.join(root, "git_smudge"), outside)
    shutil.move(os.path.join(root, "git_smudge"), os.path.join(subs, "git_smudge"))
    expected["git_smudge"] = ({"uniform": 10}, "graded", "mean radiance matches")

    # Buggy and unfinished.
    copy_labs(STUBS, os.path.join(subs, "stub"), ["branching"])
    expected["stub"] = ({"branching": 0}, "graded", "direct light only")
    with zipfile.ZipFile(os.path.join(subs, "forgot_the_third.zip"), "w") as z:
        z.write(os.path.join(MUTANTS, "uniform_no_divide", "uniform.cpp"), "labs/uniform.cpp")
    expected["forgot_the_third"] = ({"uniform": 0}, "graded", "forgot to divide by the pick probability 1/3")
    copy_labs(SOLUTIONS, os.path.join(subs, "one_broken"), ["branching"])
    write(os.path.join(subs, "one_broken", "uniform.cpp"), '#include "pathlab/lab.h"\nthis is not C++;\n')
    expected["one_broken"] = ({"branching": 10, "uniform": 0}, "does not compile: uniform", "does not compile")
    write(os.path.join(subs, "nothing", "README.txt"), "I will hand it in later\n")
    # Races between render threads that leave the image as it is, which only the race check sees.
    for lab, text in racy_labs().items():
        write(os.path.join(subs, "racy", lab + ".cpp"), text)
    expected["racy"] = ({"uniform": 0, "importance": 0}, "graded", "data race between render threads")
    expected["nothing"] = ({}, "no lab files found", "not submitted")

    # Hostile: each case one lab file, its placeholders filled in.
    fills = {"@OUTSIDE@": outside, "@SOURCE@": args.source, "@PORT@": str(port), "@SECRET@": SECRET,
             "TILE_MEANS": tile_means_table()}
    for case in sorted(os.listdir(HOSTILE)):
        for name in os.listdir(os.path.join(HOSTILE, case)):
            text = open(os.path.join(HOSTILE, case, name)).read()
            for placeholder, value in fills.items():
                text = text.replace(placeholder, value)
            write(os.path.join(subs, "hostile_" + case, name), text)
    reasons = {
        "endless_loop": "finished no sample for 4 s: an endless loop, or recursion that never ends?",
        "fork_bomb": "fork failed: Operation not permitted",
        "huge_allocation": "ran out of memory",
        "write_outside": "cannot write " + outside,
        "read_solutions": "cannot see " + os.path.join(args.source, "solutions", "branching.cpp"),
        "network_socket": "no connection to 127.0.0.1:%d" % port,
        "fake_results": "mean radiance differs",
        "include_passwd": "/etc/passwd: No such file or directory",
        "include_urandom": "does not compile",
        "compiler_bomb": "does not compile",
        # It can signal nothing: its sandbox's first process is immune, and it is the only other.
        "kill_everything": "mean radiance differs",
        "proc_snoop": "SNOOPED: nothing",
        "hidden_scene_leak": "on hidden scene 1 the lab crashed (on a hidden scene, what the lab printed is not shown)",
        "table_of_tile_means": "its pixels do not vary from seed to seed",
        "table_with_noise": "of the detail the reference image has",
        "ptrace_parent": "ptrace 1: Operation not permitted",
        "stop_itself": "stopped its own process (Stopped (signal), signal 19)",
        "widen_affinity": "sched_setaffinity: Operation not permitted",
        "seed_offset": "too noisy to judge",
        "rare_spikes": "too noisy to judge",
        "control_characters": "GRADER OK",
        # Its forged replay is set aside: the words are its bug's, from the renders.
        "forged_replay": "likely cause: emission after a specular bounce missing",
    }
    reasons["hanging_initializer"] = reasons["endless_loop"]
    for case, reason in reasons.items():
        expected["hostile_" + case] = ({"branching": 0}, "graded", reason)
    # A lab 5 whose lobe dump is rewritten after the viewer wrote it: the grader, which reads the
    # numbers as untrusted, cannot read it as the dump it asked for.
    # Code compiled only under ThreadSanitizer (a symbol that exists nowhere): its build of the
    # lab does not load, which the race check holds against the lab.
    expected["hostile_race_hidden_from_tsan"] = (
        {"branching": 0}, "graded", "the lab compiled with ThreadSanitizer does not load")
    expected["hostile_forged_lobe_dump"] = (
        {"glossy": 0}, "graded",
        "the lobe check could not read what the lab's process wrote: it is not the lobe dump")
    # Correct where it is not timed, and on the timing core (the first) it cuts corners: the
    # correctness renders run on the other core, so only the speed points go.
    expected["hostile_timed_run_detector"] = ({"uniform": 10 - SPEED_POINTS}, "graded",
                                              "the timed runs rendered other images than the same seeds did")
    expected["hostile_floods_output"] = ({"branching": 10}, "graded",
                                         "it printed more than 4 MiB: what followed was not read")
    # Only the hanging lab's points are lost: each lab is loaded from a library of its own.
    copy_labs(SOLUTIONS, os.path.join(subs, "hostile_hanging_initializer"), ["uniform", "importance", "roulette"])
    expected["hostile_hanging_initializer"] = (
        {"branching": 0, "uniform": 10, "importance": 10, "roulette": 10}, "graded", reasons["hanging_initializer"])
    os.symlink(os.path.join(SOLUTIONS, "branching.cpp"), os.path.join(subs, "hostile_fake_results", "roulette.cpp"))
    write(os.path.join(subs, "oversized", "branching.cpp"), "// padding\n" * 30000)
    expected["oversized"] = ({}, "no lab files found", "more than the 262144 allowed")
    with zipfile.ZipFile(os.path.join(subs, "zip_slip_and_bomb.zip"), "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("../../../../../.." + outside + "/escaped.cpp", "int escaped;\n")
        z.writestr("bomb/zeros.bin", b"\0" * (300 << 20))
        z.write(os.path.join(SOLUTIONS, "branching.cpp"), "branching.cpp")
    expected["zip_slip_and_bomb"] = ({"branching": 10}, "graded", "mean radiance matches")
    # A repository whose refs folder is a link to / and whose HEAD names a file beyond it: the
    # intake reads no file out of the repository's folder, and quotes none.
    repository = os.path.join(subs, "git_refs_link")
    committed_repository(repository, ["branching"])
    shutil.rmtree(os.path.join(repository, ".git", "refs"))
    os.symlink("/", os.path.join(repository, ".git", "refs"))
    write(os.path.join(repository, ".git", "HEAD"), "ref: refs/proc/self/environ\n")
    expected["git_refs_link"] = ({}, "no lab files found", "refs/proc/self/environ is missing")
    return subs, expected


# The reference solutions with shared state their images never use: a global counter, and a
# function-local static that every thread reads and writes. The line of each race, as feedback
# names it, is the line holding the marker comment. Each races on every call: a race over
# before TBB's second thread joins the render, such as a running maximum of the depth (written
# only while it grows, in the first samples), is one the race check cannot see, as
# docs/instructor-guide.md says; under CI's load such a lab here went unnoticed.
RACES = {
    "uniform": ("Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {\n",
                "int samplesTraced = 0;\n\n", "    ++samplesTraced; // RACE\n", "samplesTraced"),
    "importance": ("Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {\n", "",
                   "    static long callsSoFar = 0;\n    ++callsSoFar; // RACE\n",
                   "callsSoFar"),
}


def racy_labs():
    """{lab: source}: each lab of RACES, made from its reference solution."""
    labs = {}
    for lab, (signature, before, after, _) in RACES.items():
        text = open(os.path.join(SOLUTIONS, lab + ".cpp")).read()
        check(signature in text, f"solutions/{lab}.cpp has the line the racy lab is made at")
        labs[lab] = text.replace(signature, before + signature + after)
    return labs


def race_lines(labs):
    """{lab: 'labs/LAB.cpp:N: data race between render threads on `VARIABLE`'}, as feedback says."""
    lines = {}
    for lab, text in labs.items():
        number = next(i for i, line in enumerate(text.splitlines(), 1) if "// RACE" in line)
        lines[lab] = f"labs/{lab}.cpp:{number}: data race between render threads on `{RACES[lab][3]}`"
    return lines


def races_found(out):
    """The race check's verdicts: the racy labs' lines named in feedback.json, and no race in the
    correct submission's labs."""
    feedback = json.load(open(os.path.join(out, "submissions", "racy", "feedback.json")))
    details = {lab["lab"]: " ".join(c["details"][0] if c["details"] else "" for c in lab["checks"]
                                    if c["name"] == "correctness") for lab in feedback["labs"]}
    for lab, line in race_lines(racy_labs()).items():
        check(details.get(lab, "").startswith(line), f"racy {lab}: feedback.json names the race: {line}"
              + ("" if details.get(lab, "").startswith(line) else f" (got: {details.get(lab)})"))
    correct = json.load(open(os.path.join(out, "submissions", "correct", "feedback.json")))
    clean = [lab["lab"] for lab in correct["labs"] for c in lab["checks"] if c["name"] == "correctness"
             and any(d.startswith("no data race between render threads") for d in c["details"])]
    check(sorted(clean) == sorted(LABS), "the reference solutions: the race check ran on each lab and "
          f"found no race (said for {sorted(clean)})")


def test_rubric(root):
    rubric = json.load(open(os.path.join(args.source, "grader", "rubric.json")))
    rubric["correctness"]["seeds"] = 4
    # Two timed runs each, and no threshold: this test checks verdicts (a correct lab gets its
    # speed points, a wrong one none), not how steady this machine's timings are
    # (tests/grader/grader_test.py and its --slow do). On the 2-core CI machine, alone, a
    # correct submission's branching lab measured 0.67 times the reference (the same code), and
    # in Debian 13 runs below 0.5 and once below 0.25. Branching's timed render is the shortest:
    # graded with 2 threads, 0.3 s once the start-up (0.45 to 0.65 s) is subtracted, while a
    # run's time varies by 0.1 to 0.5 s on this machine.
    rubric["speed"].update({"runs": 2, "min_ratio": 0.0})
    rubric["limits"]["seconds_per_run"] = 8
    path = os.path.join(root, "rubric.json")
    json.dump(rubric, open(path, "w"))
    return path


def run_batch(subs, out, rubric, jobs=2, extra=()):
    start = time.time()
    run = subprocess.run([GRADER, "batch", subs, "--out", out, "--jobs", str(jobs), "--rubric", rubric, *extra],
                         capture_output=True, text=True, timeout=1500)
    return run, time.time() - start


def gradebook(out):
    return {row["id"]: row for row in csv.DictReader(open(os.path.join(out, "gradebook.csv")))}


def sandbox_processes(root):
    """Processes of this test's gradings left running as a sandbox user (uids 3,500,000 and up,
    with this test's folder on their command line), after giving killed ones a moment to go."""
    for _ in range(30):
        ps = subprocess.run(["ps", "-eo", "uid=,pid=,stat=,args="], capture_output=True, text=True).stdout
        left = [line for line in ps.splitlines() if int(line.split()[0]) >= 3_500_000 and root in line]
        if not left:
            return []
        time.sleep(0.1)
    print("left running:\n" + "\n".join(left))
    return left


# Each lab's full marks and speed points in grader/rubric.json.
FULL_MARKS, SPEED_POINTS = 10, 2


def verdicts(out, expected):
    rows = gradebook(out)
    check(set(rows) == set(expected), f"the gradebook has one row per submission ({len(expected)})")
    for id_, (scores, status, words) in sorted(expected.items()):
        row = rows.get(id_)
        if row is None:
            continue
        feedback_path = os.path.join(out, "submissions", id_, "feedback.json")
        feedback = open(feedback_path).read() if os.path.exists(feedback_path) else ""
        got = {lab: float(row[lab]) for lab in LABS}
        want = {lab: float(scores.get(lab, 0)) for lab in LABS}
        # A correct lab (full marks expected) may lose its speed points (2) to this machine's timing on 2 cores, which
        # this test does not judge (grader.checks and grader.slow do): said, not failed.
        speed_only = {lab: want[lab] for lab in LABS
                      if want[lab] == FULL_MARKS and got[lab] == FULL_MARKS - SPEED_POINTS}
        if speed_only:
            print(f"note: {id_}: {sorted(speed_only)} lost only the speed points on this machine")
            got.update(speed_only)
        check(got == want and status in row["status"] and words in feedback,
              f"{id_}: scores {want}, status '{status}', feedback says '{words}'"
              + ("" if got == want else f" (got {got})") + ("" if status in row["status"] else f" (status {row['status']})"))
    return rows


def files_under(folder):
    """Every regular file below `folder`, with its bytes."""
    for top, _, names in os.walk(folder):
        for name in names:
            path = os.path.join(top, name)
            if os.path.isfile(path) and not os.path.islink(path):
                yield path, open(path, "rb").read()


def attacks_held(out, expected):
    """What the hostile submissions tried, beyond their verdicts, came to nothing; each check
    names the attack it stands for."""
    leaked = [path for path, data in files_under(out) if SECRET.encode() in data]
    check(not leaked, f"the grader's environment reached no file of the batch's output ({leaked[:3]})")
    # What goes back to a student: feedback.json, index.html, grader.log (not the lab's own
    # source, which holds the words it looks for).
    text = lambda id_: "".join(open(os.path.join(out, "submissions", id_, name), errors="replace").read()
                               for name in ("feedback.json", "index.html", "grader.log"))
    ptrace = text("hostile_ptrace_parent")
    check(not any(word in ptrace for word in ("ATTACHED", "WROTE", "OPENED", "ESCAPED")),
          "no process of the sandbox was attached to, written or left for a shell")
    check("process_vm_writev 1: Operation not permitted" in ptrace and "/proc/1/mem: Permission denied" in ptrace,
          "process_vm_writev and /proc/1/mem were refused")
    variant_lines = [line.strip() for path in sorted(os.listdir(os.path.join(out, ".variants")))
                     if path.endswith(".mtl") for line in open(os.path.join(out, ".variants", path))
                     if line.strip() and not line.startswith("#")]
    leak = text("hostile_hidden_scene_leak")
    shown = [line for line in variant_lines if line in leak or line[::-1] in leak]
    # "LEAK " with its space: the page's base64 pictures hold any four letters now and then.
    check(variant_lines and not shown and "LEAK " not in leak,
          f"nothing of the hidden scene's files reached the feedback of the lab that printed them ({shown[:3]}; "
          f"{len(variant_lines)} lines of the variant's materials; what it printed: "
          f"{[line[:80] for line in leak.splitlines() if 'LEAK ' in line][:3]})")
    # A lab's escape sequences and bells, printed or in a compiler error, arrive as \xNN text.
    raw = [name for name in ("feedback.json", "index.html", "grader.log", "result.json")
           if any(byte in open(os.path.join(out, "submissions", "hostile_control_characters", name), "rb").read()
                  for byte in (b"\x1b", b"\x07"))]
    check(not raw and "PWNED-TITLE" in text("hostile_control_characters"),
          f"no control byte a lab printed or put in a compiler error reaches its feedback or logs ({raw})")
    smudged = text("git_smudge")
    check("SMUDGED" not in smudged and "uid=" not in smudged,
          "a git submission's smudge filter did not run: its lab was read as the blob committed")
    print(f"grading time per submission, from batch.log: {grading_seconds(out)}")


def grading_seconds(out):
    """{id: seconds} from batch.log's 'done' lines."""
    seconds = {}
    for line in open(os.path.join(out, "batch.log")):
        done = re.search(r" done (\S+): .*, (\d+) s(?: \(|$)", line)
        if done:
            seconds[done.group(1)] = int(done.group(2))
    return seconds


def main():
    os.environ["PATHLAB_TEST_SECRET"] = SECRET
    with tempfile.TemporaryDirectory() as root:
        os.chmod(root, 0o755)
        outside = os.path.join(root, "outside")
        os.makedirs(outside)
        listener = Listener()
        subs, expected = make_class(root, outside, listener.port)
        rubric = test_rubric(root)
        out = os.path.join(root, "out")

        run, seconds = run_batch(subs, out, rubric)
        print(run.stdout + run.stderr[-3000:])
        check(run.returncode == 0, "grader batch finishes with status 0 whatever the submissions did")
        print(f"batch of {len(expected)} submissions with --jobs 2: {seconds:.0f} s", flush=True)
        rows = verdicts(out, expected)
        races_found(out)
        attacks_held(out, expected)

        # The hostile submissions had no effect outside their sandboxes.
        check(os.listdir(outside) == [], "nothing was written outside the sandboxes' scratch folders")
        check(listener.connections == 0, "no submission reached the host's network")
        check(sandbox_processes(root) == [], "no process of any submission is left running")
        passwd = open(os.path.join(out, "submissions", "hostile_include_passwd", "feedback.json")).read()
        check("root:x:0" not in passwd, "the compiler's message shows nothing of the host's /etc/passwd")
        for case in ("read_solutions", "write_outside", "network_socket"):
            text = open(os.path.join(out, "submissions", "hostile_" + case, "feedback.json")).read()
            check("READ " not in text and "WROTE " not in text and "CONNECTED " not in text,
                  f"hostile {case}: no attempt succeeded")
        intake = json.load(open(os.path.join(out, "submissions", "hostile_fake_results", "result.json")))["intake"]
        check(any("not a regular file" in p for p in intake["problems"]) and "roulette.cpp" not in intake["taken"],
              "a symbolic link in a submission is not followed")
        summary = open(os.path.join(out, "summary.html")).read()
        row = re.search(r"<tr>(?:(?!</tr>).)*forgot to divide by the pick probability 1/3(?:(?!</tr>).)*</tr>",
                        summary)
        check("<svg" in summary and row and 'href="submissions/forgot_the_third/index.html"' in row.group(0)
              and "<h2>Labs</h2>" in summary and "correctness passed" in summary,
              "the summary page has the histogram, the labs' pass rates and the diagnoses with whom they apply to"
              + (f" (the diagnosis's row: {row.group(0)})" if row else " (no row with the diagnosis)"))
        if not args.class_only:
            bookkeeping(root, subs, out, rubric, expected, rows)
        listener.running = False
    finish()


def bookkeeping(root, subs, out, rubric, expected, rows):
    """The batch run again, killed and restarted, and sharded, each against the first run's
    gradebook `rows`. These are the grader's own bookkeeping, the same with or without the race
    check, which the first batch has tested: here it is left out (each batch would otherwise run
    its canary and every finished lab under ThreadSanitizer again)."""
    started = time.monotonic()
    no_race = ["--no-race-check"]

    # Run again: everything is done, nothing is graded, the gradebook is the same.
    before = open(os.path.join(out, "gradebook.csv")).read()
    run, _ = run_batch(subs, out, rubric, extra=no_race)
    check(f"{len(expected)} submission(s) already graded" in run.stderr
          and open(os.path.join(out, "gradebook.csv")).read() == before,
          "a batch run again skips what is graded and keeps the gradebook")
    check("did not finish" not in run.stderr and "0 of 0" not in run.stderr,
          f"... and says nothing of an interrupted batch or of grading none: {run.stderr[-300:]!r}")
    # The same folder, the instructor's --rubric forgotten: refused, naming both files, and
    # nothing changes (the kit's rubric would grade the class again).
    forgot = subprocess.run([GRADER, "batch", subs, "--out", out, *no_race],
                            capture_output=True, text=True, timeout=600)
    check(forgot.returncode == 2 and f"was graded under the rubric {os.path.abspath(rubric)}" in forgot.stderr
          and open(os.path.join(out, "gradebook.csv")).read() == before,
          f"a batch rerun without the --rubric it was graded under refuses, naming it: {forgot.stderr[-300:]!r}")
    print(f"run again: {time.monotonic() - started:.0f} s", flush=True)
    started = time.monotonic()

    # Killed half-way and restarted: the same rows.
    part = ["stub", "one_broken", "hostile_include_passwd", "hostile_fork_bomb", "nothing", "oversized"]
    part_subs = os.path.join(root, "part")
    os.makedirs(part_subs)
    for id_ in part:
        shutil.copytree(os.path.join(subs, id_), os.path.join(part_subs, id_), symlinks=True)
    part_out = os.path.join(root, "part_out")
    batch = subprocess.Popen([GRADER, "batch", part_subs, "--out", part_out, "--jobs", "1", "--rubric", rubric,
                              *no_race],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    # A second batch into the same folder while the first runs refuses, naming the first.
    while batch.poll() is None and not os.path.exists(os.path.join(part_out, "batch.log")):
        time.sleep(0.1)
    second, _ = run_batch(part_subs, part_out, rubric, extra=no_race)
    said = second.stderr.strip().splitlines()
    check(second.returncode == 2 and len(said) == 1
          and f"is being written by another grader batch (process {batch.pid}, started at" in said[0],
          "a second batch into the folder a batch is writing refuses in one line naming the first's "
          f"process (said: {said})")
    deadline = time.time() + 300
    while time.time() < deadline and batch.poll() is None:
        done = [i for i in part if os.path.exists(os.path.join(part_out, "submissions", i, "result.json"))]
        if len(done) >= 2:
            break
        time.sleep(0.2)
    batch.send_signal(signal.SIGKILL)
    batch.wait()
    time.sleep(1)
    check(sandbox_processes(root) == [], "a killed batch leaves no grading running")
    run, _ = run_batch(part_subs, part_out, rubric, extra=no_race)
    check("already graded" in run.stderr, "the restarted batch skips what the killed one finished")
    check("did not finish (interrupted)" in run.stderr,
          f"... and says that the batch before it did not finish: {run.stderr[:300]!r}")
    left = [f for f in os.listdir("/tmp") if f.startswith(f"pathlab-grader-{batch.pid}-")]
    check(left == [], f"the killed batch's scratch folder is removed by the next grader: {left}")
    restarted = gradebook(part_out)
    for i in part:
        differing = {k: (rows[i].get(k), v) for k, v in restarted.get(i, {}).items() if rows[i].get(k) != v}
        if differing:
            print(f"{i}: the restarted batch's row differs: {differing}")
    check(all(restarted[i] == rows[i] for i in part) and len(restarted) == len(part),
          "the restarted batch's gradebook rows equal the uninterrupted batch's")
    print(f"killed and restarted: {time.monotonic() - started:.0f} s", flush=True)
    started = time.monotonic()

    # Sharded as on a Slurm cluster: the array task's script run by hand for each shard,
    # then the merge job's; the merged gradebook equals the unsharded one.
    slurm = os.path.join(args.source, "grader", "slurm")
    shard_out = os.path.join(root, "sharded")
    # grade-class.sh gives every task one seed of the scene variants; so does this test.
    environment = dict(os.environ, PATHLAB_BUILD=os.path.abspath(args.build), SLURM_ARRAY_TASK_COUNT="2",
                       SLURM_CPUS_PER_TASK="2", PATHLAB_RUBRIC=rubric, PATHLAB_OPTIONS=" ".join(no_race),
                       PATHLAB_VARIANT_SEED="12345")
    # Both tasks at once, as the array's tasks run on a cluster (each takes one job on 2 CPUs).
    tasks = [subprocess.Popen([os.path.join(slurm, "grade-shard.sbatch"), part_subs, shard_out],
                              env=dict(environment, SLURM_ARRAY_TASK_ID=task),
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
             for task in ("0", "1")]
    check(all(task.wait() == 0 for task in tasks), "each shard's task finishes with status 0")
    merge = subprocess.run([os.path.join(slurm, "merge.sbatch"), shard_out, "2"], env=environment,
                           capture_output=True, text=True)
    shards_seen = [len(gradebook(os.path.join(shard_out, "shard-" + k))) for k in ("0", "1")]
    if merge.returncode != 0:
        print("merge.sbatch said:\n" + merge.stdout + merge.stderr)
    check(merge.returncode == 0 and shards_seen == [3, 3]
          and open(os.path.join(shard_out, "gradebook.csv")).read()
          == open(os.path.join(part_out, "gradebook.csv")).read(),
          "two shards of 3 submissions merge into the gradebook of the unsharded batch")
    print(f"sharded: {time.monotonic() - started:.0f} s", flush=True)


main()
