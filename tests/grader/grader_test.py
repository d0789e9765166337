#!/usr/bin/env python3
"""The grader against known answers: the reference solutions submitted as a student's labs
pass every check; the lab stubs fail with a diagnosis; every mutant in mutants.json fails by
the intended check with the intended words (or passes it: a lab that differs from the solutions
without a bug, or one graded under a rubric of its own); the report formats are well formed.

--part timed runs the gradings whose verdict rests on the frame-rate check (the solutions, and
the mutants judged by their speed), which nothing may run beside (ctest `grader.checks`);
--part untimed the rest (the stubs, and the mutants judged with --no-speed), which can share the
machine (ctest `grader.mutants`). Without --part, both.

--slow adds the mutants that need the frame-rate check and a false-fail validation: 200
gradings of the solutions' correctness and noise with distinct seeds, which should all pass
(each correctness check has a family-wise false-fail rate <= 1e-3 before its retry on fresh
seeds, so about 1e-6 after it).
"""
import json
import os
import subprocess
import tempfile
import time
import xml.etree.ElementTree as ET

from support import LABS, UNBIASED, arguments, check, finish, grader

args = arguments((["--slow"], {"action": "store_true"}),
                 (["--part"], {"choices": ("timed", "untimed")}))
GRADER = grader(args)


def grade(viewer, extra, tmp, name):
    report = os.path.join(tmp, name + ".json")
    run = subprocess.run([GRADER, "--viewer", viewer, "--json", report, *extra],
                         capture_output=True, text=True, timeout=1800)
    if not os.path.exists(report):
        return run, None
    return run, json.load(open(report))


def fast_rubric(tmp):
    """The public rubric with a short per-run time limit, so the endless-loop mutant is quick."""
    rubric = json.load(open(os.path.join(args.source, "grader", "rubric.json")))
    rubric["limits"]["seconds_per_run"] = 10
    rubric["limits"]["memory_mb"] = 2048
    path = os.path.join(tmp, "rubric.json")
    json.dump(rubric, open(path, "w"))
    return path


def solutions_pass(tmp):
    out = {k: os.path.join(tmp, "solutions." + k) for k in ("xml", "gradescope.json", "html", "md")}
    run, report = grade(os.path.join(args.build, "viewer_solutions_as_student"),
                        ["--junit", out["xml"], "--gradescope", out["gradescope.json"], "--html", out["html"],
                         "--report", out["md"]],
                        tmp, "solutions")
    print(run.stdout)
    check(run.returncode == 0 and report is not None, "the solutions, graded as a student's labs, pass (exit 0)")
    if report:
        for lab in report["labs"]:
            for c in lab["checks"]:
                check(c["passed"], f"solution {lab['lab']}: {c['name']} passes ({c['summary']})")
        check(set(report["speed_ratios"]) == {f"{lab}/branching" for lab in LABS[1:]},
              "the speed ratios between labs are reported")
    # Gradescope's results.json: the fields and types its specification asks for.
    g = json.load(open(out["gradescope.json"]))
    check(isinstance(g["score"], (int, float)) and isinstance(g["execution_time"], int)
          and isinstance(g["output"], str) and isinstance(g["tests"], list) and len(g["tests"]) == 3 * len(LABS),
          f"Gradescope results.json has score, execution_time, output and {3 * len(LABS)} tests")
    check(all(isinstance(t["name"], str) and isinstance(t["score"], (int, float))
              and isinstance(t["max_score"], (int, float)) and t["status"] in ("passed", "failed")
              and isinstance(t["output"], str) and t["visibility"] in ("visible", "hidden", "after_due_date", "after_published")
              for t in g["tests"]), "every Gradescope test has name, score, max_score, status, output, visibility")
    suites = ET.parse(out["xml"]).getroot()
    check(suites.tag == "testsuites" and len(suites.findall(".//testcase")) == 3 * len(LABS)
          and not suites.findall(".//failure"),
          f"the JUnit XML parses: {3 * len(LABS)} test cases, no failures")
    # The lab report: each notebook row's figures, yours and the reference's, the ratios between
    # labs, and the checks; its noise is the figure a headless render of the same lab prints.
    sections = {}  # the table rows under each "## " heading
    heading = ""
    for line in open(out["md"]):
        if line.startswith("## "):
            heading = line[3:].strip()
        elif line.startswith("| ") and "---" not in line:
            sections.setdefault(heading, []).append(
                [cell.strip() for cell in line.split("|")[1:-1]])
    rows = [row for table in sections.values() for row in table]
    # estimator, correct, frame rate yours and the reference's, samples per CPU-second, noise and
    # efficiency, each yours and the reference's.
    # One row per lab, and a second for each roulette lab (at the graded continueProb).
    notebook_rows = len(LABS) + len(UNBIASED)
    figures = [r for r in rows if len(r) == 10 and r[1] in ("yes", "**no**")]
    check(len(figures) == notebook_rows and all(r[1] == "yes" and "fps" in r[2] and "fps" in r[3]
                                    and all(float(c) > 0 for c in r[4:]) for r in figures),
          f"the lab report has the {notebook_rows} notebook rows, yours and the reference's: "
          f"{figures}")
    ratios = sections.get("Ratios between the labs", [])[1:]
    check(len(ratios) == notebook_rows and all(float(r[1]) > 0 for r in ratios),
          "the lab report has the ratios between labs")
    # Lab 4 at 64 and 256 spp, the solution as the reference: the same deterministic noise, and
    # at the graded continueProb (finite variance) a ratio of about 0.5.
    late = sections.get("Lab 4: the noise at 64 and at 256 spp", [])[1:]
    graded = next((r for r in late if "as graded" in r[0]), None)
    check(len(late) == 2 and all(r[3] == r[4] and float(r[3]) > 0 for r in late) and graded
          and 0.4 < float(graded[5]) < 0.6,
          f"the lab report has lab 4's noise at 64 and 256 spp, yours as the reference's: {late}")
    importance = next((r for r in figures if r[0].startswith("importance")), None)
    stats = os.path.join(tmp, "report-importance.json")
    subprocess.run([os.path.join(args.build, "viewer_solutions_as_student"), "-c",
                    os.path.join(args.source, "models", "cornell_box_VI2_Specular.ecs"),
                    "--lab", "importance", "--size", "512", "512", "--spp", "64",
                    "-o", os.path.join(tmp, "report-importance.pfm"), "--stats", stats],
                   check=True, capture_output=True)
    headless = json.load(open(stats))["noise"]
    check(importance is not None and importance[6] == f"{headless:.3f}",
          f"the report's noise of lab 3 ({importance[6] if importance else None}) is a headless "
          f"render's ({headless:.3f})")
    html = open(os.path.join(out["html"], "index.html")).read()
    check(html.count("data:image/png;base64,") >= 12, "the HTML report embeds its images")


def stubs_fail(tmp):
    for lab in ("branching", "roulette"):
        run, report = grade(os.path.join(args.build, "viewer"), ["--lab", lab, "--no-speed"], tmp, "stub-" + lab)
        correctness = report["labs"][0]["checks"][0] if report else None
        text = json.dumps(correctness, ensure_ascii=False)
        check(run.returncode == 1 and correctness and not correctness["passed"]
              and "direct light only" in text, f"the {lab} stub fails correctness, diagnosed as direct light only")


def rubric_with(tmp, name, base, changes):
    """`base` (a rubric file) with `changes` merged in, section by section."""
    rubric = json.load(open(base))

    def merge(into, changes):
        for key, value in changes.items():
            if isinstance(value, dict) and isinstance(into.get(key), dict):
                merge(into[key], value)
            else:
                into[key] = value

    merge(rubric, changes)
    path = os.path.join(tmp, f"rubric-{name}.json")
    json.dump(rubric, open(path, "w"))
    return path


def mutants(tmp, slow, timed=(True, False)):
    """Each entry of mutants.json: the check that `fails` (or `passes`: a correct lab unlike the
    solutions, or one under a rubric of its own) and the words the feedback must contain (`says`: one string or several). An entry
    may grade another entry's lab (`mutant`) under a changed rubric (`rubric`). `timed`: the
    entries judged by the speed check (True), the others (False), or both."""
    table = json.load(open(os.path.join(args.source, "tests", "grader", "mutants.json")))["mutants"]
    rubric = fast_rubric(tmp)
    rows = []
    replays = {"ran": 0, "named": 0}
    for name, m in sorted(table.items()):
        if m.get("slow", False) != slow:
            continue
        target_name = m.get("fails") or m.get("passes")
        if (target_name == "speed") not in timed:
            continue
        should_pass = "passes" in m
        mutant_rubric = rubric_with(tmp, name, rubric, m["rubric"]) if "rubric" in m else rubric
        extra = ["--lab", m["lab"], "--rubric", mutant_rubric]
        if target_name != "speed":
            extra.append("--no-speed")
        viewer = os.path.join(args.build, "mutants", m.get("mutant", name))
        started = time.monotonic()
        run, report = grade(viewer, extra, tmp, name)
        seconds = time.monotonic() - started
        checks = {c["name"]: c for c in report["labs"][0]["checks"]} if report else {}
        target = checks.get(target_name)
        text = json.dumps(target, ensure_ascii=False) if target else ""
        passed = bool(target and target["passed"])
        verdict = ("passed" if passed else "failed") if target else "NOT GRADED"
        diagnosis = next((d for d in (target or {}).get("details", []) if d.startswith("likely cause")),
                         (target or {}).get("summary", ""))
        rows.append(f"| {name} | {m['lab']} | {target_name}: {verdict} | {diagnosis[:110]} | {seconds:.0f} s |")
        says = m["says"] if isinstance(m["says"], list) else [m["says"]]
        missing = [words for words in says if words not in text]
        # Words of another cause that must not be told (a linear lab is not called non-linear).
        wrong = [words for words in m.get("never_says", []) if words in text]
        check(report is not None and target is not None and passed == should_pass and not missing
              and not wrong,
              f"mutant {name}: {target_name} {'passes' if should_pass else 'fails'} and says "
              f"{says}" + (f", never {m['never_says']}" if "never_says" in m else "")
              + (f" (missing: {missing}; it said: {text[:600]})" if missing else "")
              + (f" (it said {wrong}: {text[:600]})" if wrong else ""))
        replay = next((d for d in (target or {}).get("details", []) if d.startswith("replay:")), None)
        if replay:
            replays["ran"] += 1
            replays["named"] += "replay" in m and m["replay"] in replay
        if "replay" in m:
            check(replay is not None and m["replay"] in replay,
                  f"mutant {name}: the replay beside the reference says '{m['replay']}'"
                  + ("" if replay and m["replay"] in replay else f" (it said: {replay})"))
    print("\n| mutant | lab | verdict | diagnosis | grading |\n|---|---|---|---|---|\n" + "\n".join(rows) + "\n")
    print(f"the replay ran for {replays['ran']} mutants and said what mutants.json expects for "
          f"{replays['named']} of them")


def false_fail_validation(tmp, gradings=200):
    fails = 0
    for i in range(gradings):
        lab = LABS[i % len(LABS)]
        run, report = grade(os.path.join(args.build, "viewer_solutions_as_student"),
                            ["--lab", lab, "--no-speed", "--seed", str(1000 + i)], tmp, "validation")
        passed = report is not None and all(c["passed"] for c in report["labs"][0]["checks"])
        fails += not passed
        if not passed:
            print(f"false fail: {lab} seed {1000 + i}: {run.stdout}", flush=True)
        if (i + 1) % 20 == 0:
            print(f"validation: {i + 1} of {gradings} gradings, {fails} failed", flush=True)
    print(f"false-fail validation: {fails} of {gradings} gradings of correct labs failed", flush=True)
    check(fails == 0, "no correct lab failed in the validation")


with tempfile.TemporaryDirectory() as tmp:
    if args.slow:
        mutants(tmp, slow=True)
        false_fail_validation(tmp)
    else:
        if args.part != "untimed":
            solutions_pass(tmp)
            mutants(tmp, slow=False, timed=(True,))
        if args.part != "timed":
            stubs_fail(tmp)
            mutants(tmp, slow=False, timed=(False,))
finish()
