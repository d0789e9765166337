#!/usr/bin/env python3
"""An instructor's term, end to end, with the real grader and sandbox: a hidden scene added as
docs/instructor-guide.md shows, a class graded, the scene's light edited and the class graded
again, a reference made wrong on purpose, the rubric changed, one student regraded, and the
Gradescope zip made with the hidden scene git does not track. Each step checks what the guide
promises:

- the canary (the solutions graded first) passes with the edited scene, so its reference was
  measured again; and stops the batch, grading no one, when a reference is wrong;
- results graded under another rubric are kept and marked stale with --keep-stale, and no gradebook
  mixes totals out of different maxima; --only grades just those named; a rubric that changed only
  points or thresholds re-scores everyone from their measurements, rendering nothing (the canary
  too), each grading kept as an attempt that the student's page lists; a submission changed since
  it was graded is graded again without --only, saying so;
- a batch prints its time estimate before its gradings (per submission, the class, a Slurm
  array) and the measured figure at the end;
- a late policy in the rubric (slip days, a penalty per day, a cap, an extension) gives each
  student's late days, slip days used, penalty and final total, which lms.csv exports; with a
  deadline per lab and the LMS's time per lab, each late lab loses from its own points and the
  slip days are one budget spent in the order the labs were due;
- a regrade says, per student, the old and new total and each changed check with its reason (the
  terminal, regrades.csv, summary.html); a total it lowers on the same files is withheld from
  lms.csv until the rubric's regrades.lower_scores decides, and keep_higher keeps the higher one
  without grading anyone again;
- no file of a student's feedback names the hidden scene or shows its images;
- per-student variants: each student's feedback names their own furnace and no other's; a
  student's variant folder is the variant the batch graded, and a local grade on it passes the
  solutions and fails an edited one;
- the similarity report puts a copy of the solutions with renamed variables in one cluster with
  the solutions, with side-by-side pages.

The rubric is the kit's, lighter (32x32 pixels, 6 seeds (with 4, a t-test of 3 degrees of
freedom can miss even a reference wrong by half after the Holm correction), the furnace as the only public scene,
no speed check), so that the whole term takes a few minutes; the checks are the same.
"""
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import zipfile

from support import LABS, LOBE, arguments, check, finish, grader, write

args = arguments((["--keep"], {"help": "work in this (new) folder and keep it, to look at afterwards"}))
GRADER = grader(args)
SOLUTIONS = os.path.join(args.source, "solutions")
MODELS = os.path.join(args.source, "models")
SECRET = "secret_lantern"  # the hidden scene's name: no student may read it
timings = {}


def read(path):
    with open(path, errors="replace") as f:
        return f.read()


def add_hidden_scene(folder):
    """The guide's example (the VI2 box with a warmer light), under the secret name."""
    os.makedirs(folder, exist_ok=True)
    box = os.path.join(MODELS, "cornell_box_VI2_Specular")
    obj = re.sub(r"(?m)^mtllib .*$", f"mtllib {SECRET}.mtl", read(box + ".obj"))
    write(os.path.join(folder, SECRET + ".obj"), obj)
    write(os.path.join(folder, SECRET + ".mtl"), re.sub(r"(?m)^Ke .*$", "Ke 20 14 8", read(box + ".mtl")))
    write(os.path.join(folder, SECRET + ".ecs"), read(box + ".ecs").replace("cornell_box_VI2_Specular", SECRET))


def renamed(source):
    """A lab file with its local names changed and its comments dropped: a disguised copy."""
    for old, new in (("hit", "h"), ("radiance", "L"), ("component", "which"), ("throughput", "beta"),
                     ("pickProbability", "p"), ("strength", "s"), ("m", "mat")):
        source = re.sub(rf"(?<![.>])\b{old}\b", new, source)  # not a member: light.radiance stays
    return re.sub(r"(?m)^\s*//.*\n", "", source)


def make_class(root):
    subs = os.path.join(root, "subs")
    for lab in LABS:
        solution = read(os.path.join(SOLUTIONS, lab + ".cpp"))
        write(os.path.join(subs, "alice", lab + ".cpp"), renamed(solution))  # the solutions, disguised
        write(os.path.join(subs, "bob", lab + ".cpp"), solution)
        if lab != "roulette":
            write(os.path.join(subs, "carol", lab + ".cpp"), solution)       # lab 4 not handed in
    shutil.copy(os.path.join(args.source, "tests", "grader", "mutants", "uniform_no_divide", "uniform.cpp"),
                os.path.join(subs, "bob", "uniform.cpp"))
    return subs


def light_rubric(root, roulette_correctness=6, max_noise_ratio=1.5, moved_points=0, lower_scores=None, late=None,
                 variants=None):
    """The kit's rubric, lighter; `moved_points` of lab 3's correctness moved to lab 2's (the
    maximum kept); `lower_scores`, the rubric's regrades.lower_scores, `late`, its late policy, and
    `variants`, its per-student variants, where given."""
    rubric = json.load(open(os.path.join(args.source, "grader", "rubric.json")))
    rubric["correctness"].update({"seeds": 6, "width": 32, "height": 32, "tiles": 2, "scenes": ["furnace"]})
    rubric["noise"].update({"scene": "furnace", "max_ratio": max_noise_ratio})
    rubric["speed"]["scene"] = "furnace"
    rubric["points"]["roulette"]["correctness"] = roulette_correctness
    rubric["points"]["importance"]["correctness"] -= moved_points
    rubric["points"]["uniform"]["correctness"] += moved_points
    if lower_scores:
        rubric["regrades"] = {"lower_scores": lower_scores}
    if late:
        rubric["late"] = late
    if variants:
        rubric["variants"] = variants
    path = os.path.join(root, "rubric.json")
    json.dump(rubric, open(path, "w"), indent=1)
    return path


# The totals, from the kit's points with --no-speed (correctness and noise, 8 a lab): the class's
# full marks; a lab lost (bob's lab 2, carol's lab 4 not handed in); after step 4 raises lab 4's
# correctness from 6 to 16, the same three.
FULL = str(8 * len(LABS))
LAB_LOST = str(8 * len(LABS) - 8)
RAISED = str(8 * len(LABS) + 10)
RAISED_LAB_LOST = str(8 * len(LABS) + 10 - 8)
RAISED_NO_LAB_4 = str(8 * len(LABS) + 10 - 18)


def batch(step, *options, references=True):
    """A batch of the class into OUT; `references` False leaves --references out, for the batch
    to take the one before's."""
    start = time.time()
    run = subprocess.run([GRADER, "batch", SUBS, "--out", OUT, "--jobs", "2", "--no-speed", "--rubric", RUBRIC,
                          *(["--references", NO_REFERENCES] if references else []), "--scenes", HIDDEN, *options],
                         capture_output=True, text=True, timeout=1200)
    timings[step] = time.time() - start
    print(f"-- {step}: exit {run.returncode}, {timings[step]:.0f} s\n{run.stdout}{run.stderr[-1500:]}", flush=True)
    return run


def gradebook():
    return {row["id"]: row for row in csv.DictReader(open(os.path.join(OUT, "gradebook.csv")))}


def graded_in_last_batch():
    """The ids the newest batch in batch.log started."""
    log = read(os.path.join(OUT, "batch.log")).split(" batch of ")[-1]
    return sorted(re.findall(r" start (\S+) \(", log))


def canaries():
    return re.findall(r"canary: reference solutions ([\d.]+) / ([\d.]+)", read(os.path.join(OUT, "batch.log")))


def feedback_files():
    """Every file a student gets: their submission folder, but its result.json (the gradebook's)."""
    for id_ in ("alice", "bob", "carol"):
        for folder, _, files in os.walk(os.path.join(OUT, "submissions", id_)):
            for name in files:
                if name != "result.json":
                    yield os.path.join(folder, name)


class _kept:
    def __init__(self, path):
        os.makedirs(path)
        self.path = os.path.abspath(path)

    def __enter__(self):
        return self.path

    def __exit__(self, *_):
        return False


def main():
    global SUBS, OUT, RUBRIC, NO_REFERENCES, HIDDEN
    with (tempfile.TemporaryDirectory() if not args.keep else _kept(args.keep)) as root:
        os.chmod(root, 0o755)
        SUBS, OUT = make_class(root), os.path.join(root, "grades")
        RUBRIC, NO_REFERENCES, HIDDEN = light_rubric(root), os.path.join(root, "references"), os.path.join(root, "hidden")
        os.makedirs(NO_REFERENCES)
        add_hidden_scene(HIDDEN)

        # 1. The class, with a hidden scene and a deadline that everyone met.
        run = batch("first grading", "--deadline", "2999-01-01T00:00Z")
        rows = gradebook()
        check(run.returncode == 0 and canaries() == [(FULL, FULL)],
              f"the canary: the solutions get {FULL}/{FULL} first")
        check([rows[i]["total"] for i in ("alice", "bob", "carol")] == [FULL, LAB_LOST, LAB_LOST]
              and all(r["max_total"] == FULL for r in rows.values()),
              f"alice (the solutions, disguised) {FULL}/{FULL}, bob (lab 2 does not divide) {LAB_LOST}, "
              f"carol (no lab 4) {LAB_LOST}")
        check(rows["carol"]["status"] == "graded; not submitted: roulette" and rows["carol"]["missing_labs"] == "roulette",
              "the status names the lab not submitted")
        check(all(rows[i]["late"] == "no" and rows[i]["submitted_at"] and len(rows[i]["files_hash"]) == 16
                  for i in rows), "every row has a submission time, a late flag and its files' hash")
        check(rows["bob"]["uniform_correctness"] == "0" and rows["bob"]["branching_correctness"] == "6"
              and rows["bob"]["uniform_speed"] == "", "a column per check (speed empty: not checked)")
        lms = read(os.path.join(OUT, "lms.csv")).splitlines()
        check(lms[0] == f"Student,SIS Login ID,PathLab ({FULL} points)" and f"alice,alice,{FULL}" in lms,
              "lms.csv")
        summary = read(os.path.join(OUT, "summary.html"))
        clusters = re.findall(r"<tr><td>(\w+)</td><td>\d+</td><td>\d+</td><td>(\d+)%</td><td>(.*?)</td></tr>", summary)
        disguised = {lab for lab, pct, members in clusters
                     if "alice &harr;" in members and "reference solutions &harr;" in members and int(pct) >= 95}
        pages = [os.path.join(OUT, link) for link in re.findall(r'href="(similarity/[^"]+)"', summary)]
        check(disguised == set(LABS) and pages and all(os.path.exists(p) for p in pages),
              "the similarity report puts alice's renamed copy in one cluster with the solutions, every lab, "
              "each member linked to a side-by-side page")

        # No feedback names the hidden scene or shows its images.
        leaks = [path for path in feedback_files() if SECRET in read(path) or "lantern" in read(path)]
        check(leaks == [], "no feedback file names the hidden scene" + (f" (found in {leaks})" if leaks else ""))
        alice = json.load(open(os.path.join(OUT, "submissions", "alice", "feedback.json")))
        correctness = [c for lab in alice["labs"] for c in lab["checks"] if c["name"] == "correctness"]
        check(all("hidden scene 1: matches its reference" in c["summary"] + "\n".join(c["details"])
                  + "\n".join(c.get("hidden_scenes", [])) for c in correctness),
              "alice's feedback says hidden scene 1 matches, by that name")
        page = read(os.path.join(OUT, "submissions", "bob", "index.html"))
        pictures = re.findall(r"<p>([^<:]+): yours, the reference", page)
        # The furnace and the parameter check per lab, and the glossy furnaces for lab 5's.
        check(len(pictures) == 2 * len(LABS) + 2 * len(LOBE) and "hidden scene 1" not in pictures,
              f"bob's page shows the furnace and the parameter check per lab, no hidden scene ({len(pictures)} pictures)")

        # 2. The instructor doubles the hidden scene's light: every result is stale (other scenes)
        # and graded again; the canary passing proves the reference was measured anew.
        mtl = os.path.join(HIDDEN, SECRET + ".mtl")
        write(mtl, read(mtl).replace("Ke 20 14 8", "Ke 40 28 16"))
        run = batch("after the scene's light changed")
        check(run.returncode == 0 and canaries()[-1] == (FULL, FULL) and graded_in_last_batch() == ["alice", "bob", "carol"],
              "an edited hidden scene: its reference measured again, the canary passes, everyone regraded")
        estimate = re.search(r"estimate: about (\d+) s per submission here \(the median of 3 earlier grading\(s\)", run.stderr)
        check(estimate and "estimate: 3 submission(s) here, 2 at a time: about " in run.stderr
              and "estimate: on a Slurm array of 10 node(s)" in run.stderr
              and re.search(r"measured: 3 submission\(s\) graded in [^,]+, 2 at a time \(estimated [^)]+\)",
                            run.stderr),
              "before its gradings, a batch prints its time estimate from the earlier gradings (here, the "
              "class, a Slurm array), and at the end the measured figure beside it")
        rows = gradebook()
        check(rows["alice"]["total"] == FULL, "alice still gets full marks on the edited scene")
        check(all(r["late"] == "no" for r in rows.values()), "a batch run again keeps its deadline")

        # 3. A reference made wrong on purpose (its expected means halved, its keys kept): the
        # canary fails and nobody is graded, nothing lost.
        cached = os.path.join(OUT, ".references", SECRET + ".json")
        reference = json.load(open(cached))
        for part in ("depth_limited", "unbiased"):
            reference[part]["mean"] = [v / 2 for v in reference[part]["mean"]]
        json.dump(reference, open(cached, "w"))
        os.remove(os.path.join(OUT, ".canary", "passed"))
        before = read(os.path.join(OUT, "gradebook.csv"))
        run = batch("a wrong reference", "--force")
        check(run.returncode != 0 and f"canary: the reference solutions score 0 / {FULL} " in run.stderr
              and "nothing was graded" in run.stderr,
              "a wrong reference: the canary fails every lab and stops the batch, saying why")
        check(read(os.path.join(OUT, "gradebook.csv")) == before, "... and the gradebook is as it was")
        os.remove(cached)  # measured again next time

        # 4. The rubric changes (lab 4's correctness worth 16): --keep-stale keeps the results and
        # marks them; their totals are out of FULL, not the new RAISED, so none is shown.
        light_rubric(root, roulette_correctness=16)
        run = batch("rubric changed, --keep-stale", "--keep-stale")
        rows = gradebook()
        check(run.returncode == 0 and graded_in_last_batch() == [], "--keep-stale grades nobody")
        check(all(r["status"].startswith("stale: graded under another rubric") and r["total"] == ""
                  and r["max_total"] == RAISED for r in rows.values()),
              f"stale results are marked, and no total out of {FULL} stands in a gradebook out of {RAISED}")
        check(len(read(os.path.join(OUT, "lms.csv")).splitlines()) == 1, "lms.csv holds no total out of another maximum")

        # 5. One student regraded.
        run = batch("--only alice", "--only", "alice")
        rows = gradebook()
        check(graded_in_last_batch() == ["alice"] and rows["alice"]["total"] == RAISED
              and rows["bob"]["total"] == "" and rows["bob"]["status"].startswith("stale"),
              "--only alice regrades alice alone; the others stay stale, without totals")

        # 6. Resumed without flags: the stale ones, whose rubric changed only in points, are judged
        # again from their measurements, nothing rendered.
        run = batch("resumed")
        rows = gradebook()
        log = read(os.path.join(OUT, "batch.log")).split(" batch of ")[-1]
        check(graded_in_last_batch() == [] and re.findall(r" (\w+): re-scored from attempt", log) == ["bob", "carol"]
              and [rows[i]["total"] for i in ("alice", "bob", "carol")] == [RAISED, RAISED_LAB_LOST, RAISED_NO_LAB_4]
              and all(not r["status"].startswith("stale") for r in rows.values()),
              f"a resumed batch re-scores what only the rubric's points made stale: every total out of {RAISED}")

        # 7. A threshold changes (noise at most 1.2 times the reference's): everyone re-scored in
        # seconds, the canary too, nothing rendered; each grading kept as an attempt.
        measured = {i: read(os.path.join(OUT, "submissions", i, "measurements.json")) for i in ("alice", "bob")}
        light_rubric(root, roulette_correctness=16, max_noise_ratio=1.2)
        run = batch("a threshold changed")
        log = read(os.path.join(OUT, "batch.log")).split(" batch of ")[-1]
        check(run.returncode == 0 and graded_in_last_batch() == [] and f"canary: reference solutions {RAISED} / {RAISED}, re-scored" in log
              and sorted(re.findall(r" (\w+): re-scored from attempt", log)) == ["alice", "bob", "carol"],
              "a threshold changed: the canary and every student re-scored from their measurements, no render")
        check(timings["a threshold changed"] < 20, f"... in seconds ({timings['a threshold changed']:.0f} s)")
        # Measurements carry over; the grading before is kept as an attempt and listed.
        kept = json.load(open(os.path.join(OUT, "submissions", "alice", "result.json")))
        attempts = sorted(os.listdir(os.path.join(OUT, "submissions", "alice", "attempts")), key=int)
        page = read(os.path.join(OUT, "submissions", "alice", "index.html"))
        check(kept["how"].startswith("re-scored from attempt") and attempts == [str(n) for n in range(1, kept["attempt"])]
              and all(f'href="attempts/{n}/index.html"' in page for n in attempts) and "Earlier attempts" in page,
              f"alice's gradings are attempts 1 to {kept['attempt']}, her page lists the earlier ones ({attempts})")
        check(json.loads(read(os.path.join(OUT, "submissions", "bob", "measurements.json")))["labs"]
              == json.loads(measured["bob"])["labs"], "a re-score measures nothing anew")
        check(gradebook()["alice"]["attempt"] == str(kept["attempt"]), "the gradebook's attempt column")
        # The log handed back with the feedback ends with the grade of now, not the one it printed.
        alice_log = read(os.path.join(OUT, "submissions", "alice", "grader.log"))
        tail = alice_log.split("The grade now:")[-1]
        check("The grade now:" in alice_log and f"total {RAISED}/{RAISED}" in tail
              and "(at most 1.2)" in tail,
              f"alice's grader.log ends with the re-score and the grade of now (total {RAISED}/{RAISED}, "
              "noise at most 1.2)" + ("" if f"total {RAISED}/{RAISED}" in tail
                                      else f"; it ends:\n{alice_log[-800:]}"))

        # 8. Carol hands in lab 4, into the folder the batch reads: graded again without --only,
        # saying so; the others kept as they are.
        write(os.path.join(SUBS, "carol", "roulette.cpp"), read(os.path.join(SOLUTIONS, "roulette.cpp")))
        run = batch("carol resubmits")
        rows = gradebook()
        check(graded_in_last_batch() == ["carol"] and "carol: changed since it was graded: graded again" in run.stderr
              and rows["carol"]["total"] == RAISED,
              "a changed submission is graded again on a plain batch run, and the run says so")

        # 9. Two points moved from lab 3's correctness to lab 2's, the maximum kept: bob, whose lab
        # 2 fails, is re-scored 2 lower on the same files. The rubric has not said whether a regrade
        # may lower a total, so lms.csv withholds his, and the terminal, the gradebook and
        # regrades.csv say from what to what, which checks and why.
        light_rubric(root, roulette_correctness=16, max_noise_ratio=1.2, moved_points=2)
        run = batch("points moved")
        rows = gradebook()
        lowered = str(int(RAISED_LAB_LOST) - 2)
        regrades = list(csv.DictReader(open(os.path.join(OUT, "regrades.csv"))))
        bob = {(r["lab"], r["check"]): r for r in regrades if r["id"] == "bob"}
        reason = "the rubric's points or thresholds changed"
        check(run.returncode == 0 and graded_in_last_batch() == []
              and re.search(rf"regrade bob: attempt \d+ -> \d+ \({reason}\): {RAISED_LAB_LOST} / {RAISED} -> "
                            rf"{lowered} / {RAISED}; importance correctness 6 -> 4\n", run.stderr)
              and "1 total(s) lowered by a regrade of the same files: withheld from lms.csv" in run.stderr,
              "points moved: the terminal says each regrade, from what to what, which check and why, and "
              "that bob's lowered total waits for the rubric's choice")
        check(set(bob) == {("total", "total"), ("importance", "correctness")}
              and (bob[("total", "total")]["before"], bob[("total", "total")]["after"]) == (RAISED_LAB_LOST, lowered)
              and bob[("importance", "correctness")]["reason"] == reason,
              f"regrades.csv: bob's total and lab 3's correctness, before and after, and why ({sorted(bob)})")
        check(rows["bob"]["total"] == lowered and "withheld from lms.csv" in rows["bob"]["status"]
              and "\nbob," not in read(os.path.join(OUT, "lms.csv")) and rows["alice"]["total"] == RAISED
              and "Regrades" in read(os.path.join(OUT, "summary.html")),
              "the gradebook shows bob's new total and why it is not exported; alice's, moved within, is whole")
        # The instructor chooses: the higher total stands. Choosing re-grades and re-scores nobody.
        light_rubric(root, roulette_correctness=16, max_noise_ratio=1.2, moved_points=2, lower_scores="keep_higher")
        run = batch("keep_higher chosen")
        rows = gradebook()
        log = read(os.path.join(OUT, "batch.log")).split(" batch of ")[-1]
        check(run.returncode == 0 and graded_in_last_batch() == [] and "re-scored from attempt" not in log
              and rows["bob"]["total"] == RAISED_LAB_LOST and rows["bob"]["graded_total"] == lowered
              and f"\nbob,bob,{RAISED_LAB_LOST}\n" in read(os.path.join(OUT, "lms.csv")),
              "regrades.lower_scores keep_higher: bob's higher total counts and is exported, nothing graded again")

        # 10. Late work: the rubric's late policy (10% a day after one slip day, at most 30%), the
        # times the LMS recorded, and carol's 3-day extension. Nothing is graded again; the
        # gradebook shows each student's late days, slip days, penalty and final total, which
        # the LMS gets.
        times = os.path.join(root, "times.csv")
        write(times, "id,submitted_at\nalice,2026-12-01T12:00Z\nbob,2026-12-04T12:00Z\ncarol,2026-12-04T12:00Z\n")
        write(os.path.join(root, "extensions.csv"), "id,days\ncarol,3\n")
        light_rubric(root, roulette_correctness=16, max_noise_ratio=1.2, moved_points=2, lower_scores="keep_higher",
                     late={"penalty_per_day": 0.1, "slip_days": 1, "max_penalty": 0.3, "extensions": "extensions.csv"})
        run = batch("late policy", "--deadline", "2026-12-01T23:59Z", "--times", times)
        rows = gradebook()
        bob_final = f"{int(RAISED_LAB_LOST) * 0.8:g}"
        lms = read(os.path.join(OUT, "lms.csv"))
        check(run.returncode == 0 and graded_in_last_batch() == []
              and [rows["bob"][c] for c in ("late", "late_days", "slip_days_used", "late_penalty", "final_total")]
              == ["yes", "3", "1", "0.2", bob_final]
              and rows["carol"]["late"] == "no" and rows["carol"]["final_total"] == RAISED
              and rows["alice"]["late_days"] == "0" and f"\nbob,bob,{bob_final}\n" in lms
              and f"\ncarol,carol,{RAISED}\n" in lms,
              f"late policy: bob 3 days late, 1 slip day, 20% off ({RAISED_LAB_LOST} -> {bob_final}, as the LMS "
              "gets it); carol on time by her extension; nothing graded again")

        # 10b. A deadline per lab: roulette due a week after the rest, and the LMS's time for each
        # of bob's labs where it has one. His branching, a day late, takes the one slip day; his
        # uniform, 3 days late, has none left and loses 30% of its own points, not of his total.
        lab_times = os.path.join(root, "lab-times.csv")
        write(lab_times, "id,lab,submitted_at\nalice,2026-12-01T12:00Z\nbob,2026-12-01T12:00Z\n"
                         "bob,branching,2026-12-02T12:00Z\nbob,uniform,2026-12-04T12:00Z\n"
                         "bob,roulette,2026-12-06T12:00Z\ncarol,2026-12-01T12:00Z\n")
        deadlines = {lab: "2026-12-01T23:59Z" for lab in ("branching", "uniform", "importance", "glossy", "mis")}
        deadlines["roulette"] = "2026-12-08T23:59Z"
        light_rubric(root, roulette_correctness=16, max_noise_ratio=1.2, moved_points=2, lower_scores="keep_higher",
                     late={"penalty_per_day": 0.1, "slip_days": 1, "max_penalty": 0.3, "deadlines": deadlines})
        # Run again without --references: the batch takes the one before's (its batch.json).
        run = batch("a deadline per lab", "--times", lab_times, references=False)
        rows = gradebook()
        bob = rows["bob"]
        lost = 0.3 * float(bob["uniform"]) / float(bob["graded_total"])
        bob_final = f"{round(100 * float(bob['total']) * (1 - lost)) / 100:g}"
        check(run.returncode == 0 and "as the batch before" in run.stderr and graded_in_last_batch() == []
              and [bob[c] for c in ("late", "late_days", "slip_days_used", "final_total", "late_labs")]
              == ["yes", "4", "1", bob_final, "branching 1 day(s) late (1 slip day(s)), uniform 3 day(s) late"]
              and rows["alice"]["late"] == "no" and f"\nbob,bob,{bob_final}\n" in read(os.path.join(OUT, "lms.csv")),
              f"a deadline per lab: bob's branching takes the slip day, his uniform loses 30% of its "
              f"{bob['uniform']} points ({bob['total']} -> {bob_final}); roulette, due later, is on time")

        # 11. Per-student variants: each student also grades on a furnace and a Cornell box of
        # their own, drawn from the class secret and their id. New scenes for everyone: the class
        # is graded again; the solutions pass every variant; each student's feedback names their
        # own furnace's numbers and no other student's; the folder `grader student-variants`
        # writes for a student holds the very variant the batch graded them on, and a local grade
        # on it passes the solutions and fails a variant whose numbers were edited.
        write(os.path.join(root, "class-secret.txt"), "a secret of this course's, 2026\n")
        variants = {"per_student": True, "secret_file": "class-secret.txt",
                    "furnace": {"albedo": [0.3, 0.7], "emission": [0.5, 2], "max_depth": [2, 6]},
                    "box": {"scene": "cornell_box_diffuse", "reflectance": [0.6, 1], "light": [0.7, 1.3]}}
        light_rubric(root, roulette_correctness=16, max_noise_ratio=1.2, moved_points=2, lower_scores="keep_higher",
                     late={"penalty_per_day": 0.1, "slip_days": 1, "max_penalty": 0.3, "extensions": "extensions.csv"},
                     variants=variants)
        run = batch("per-student variants", "--deadline", "2026-12-01T23:59Z", "--times", times)
        rows = gradebook()
        furnaces = {}
        for id_ in ("alice", "bob", "carol"):
            found = re.findall(r"your furnace \(albedo [\d.]+, Le [\d.]+, maxDepth \d\)",
                               read(os.path.join(OUT, "submissions", id_, "index.html")))
            furnaces[id_] = found[0] if found else None
        others = [(id_, path) for id_ in furnaces for path in feedback_files()
                  if f"/submissions/{id_}/" not in path and furnaces[id_] and furnaces[id_] in read(path)]
        check(run.returncode == 0 and graded_in_last_batch() == ["alice", "bob", "carol"]
              and rows["alice"]["total"] == RAISED and rows["bob"]["graded_total"] == str(int(RAISED_LAB_LOST) - 2),
              "per-student variants: new scenes, the class graded again; alice (the solutions) passes hers, "
              "bob loses no more than lab 2")
        check(all(furnaces.values()) and len(set(furnaces.values())) == 3 and others == []
              and all(os.path.exists(os.path.join(OUT, "submissions", i, "variant", "furnace.ecs")) for i in furnaces),
              f"each student's feedback names their own furnace, no other's, and holds its scene: {furnaces}"
              + (f" (another's in {others})" if others else ""))
        folders = os.path.join(root, "variants")
        made = subprocess.run([GRADER, "student-variants", "alice", "--rubric", RUBRIC, "--out", folders],
                              capture_output=True, text=True)
        alice_variant = os.path.join(folders, "alice")
        kept = json.load(open(os.path.join(alice_variant, "variant.json"))) if made.returncode == 0 else {}
        check(made.returncode == 0 and furnaces["alice"] in made.stdout and "box" in kept
              and os.path.exists(os.path.join(alice_variant, "references", kept["box"]["file"][:-4] + ".json")),
              "grader student-variants writes alice's folder: the furnace the batch graded her on, her box and "
              "its reference" + ("" if made.returncode == 0 else f": {made.stderr}"))
        local = [os.path.join(args.build, "grader"), "--viewer", os.path.join(args.build, "viewer_solutions_as_student"),
                 "--rubric", RUBRIC, "--references", NO_REFERENCES, "--scenes", "none", "--lab", "roulette",
                 "--no-speed", "--variant", alice_variant]
        graded = subprocess.run(local, capture_output=True, text=True)
        kept["furnace"]["albedo"] = round(kept["furnace"]["albedo"] + 0.1, 3)
        json.dump(kept, open(os.path.join(alice_variant, "variant.json"), "w"))
        edited = subprocess.run(local, capture_output=True, text=True)
        check(graded.returncode == 0 and edited.returncode == 1
              and f"your furnace (albedo {kept['furnace']['albedo']:g}," in edited.stdout,
              "the student's local grade on their folder passes the solutions; a folder whose albedo was edited "
              "fails on that furnace" + ("" if graded.returncode == 0 else f": {graded.stdout[-800:]}{graded.stderr[-400:]}"))

        # 12. The Gradescope zip holds a hidden scene that git does not track, and says so.
        kit = os.path.join(root, "kit")
        subprocess.run(["git", "clone", "--quiet", "--no-hardlinks", args.source, kit], check=True)
        add_hidden_scene(os.path.join(kit, "grader", "hidden_scenes"))
        # Per-student variants on Gradescope: the class secret beside the kit's rubric, untracked.
        kit_rubric = os.path.join(kit, "grader", "rubric.json")
        rubric = json.load(open(kit_rubric))
        rubric["variants"] = {"per_student": True, "secret_file": "class-secret.txt"}
        json.dump(rubric, open(kit_rubric, "w"), indent=1)
        write(os.path.join(kit, "grader", "class-secret.txt"), "a secret of this course's, 2026\n")
        tracked = subprocess.run(["git", "-C", kit, "ls-files", "grader/hidden_scenes"], capture_output=True, text=True).stdout
        zip_path = os.path.join(root, "autograder.zip")
        made = subprocess.run([sys.executable, os.path.join(kit, "scripts", "package_kit.py"), "gradescope", zip_path],
                              capture_output=True, text=True)
        names = zipfile.ZipFile(zip_path).namelist() if made.returncode == 0 else []
        check(tracked == "" and f"grader/hidden_scenes/{SECRET}.ecs" in names
              and f"grader/hidden_scenes/{SECRET}.mtl" in names and "hidden scenes packed: 1" in made.stdout,
              "make gradescope packs an untracked hidden scene and lists it")
        check("grader/class-secret.txt" in names and "packed for the autograder" in made.stdout,
              "... and the class secret its rubric names, untracked, which the autograder needs")

    print("timings: " + ", ".join(f"{step} {seconds:.0f} s" for step, seconds in timings.items()))
    finish()


main()
