#!/usr/bin/env python3
"""The path inspector's side-by-side replay (viewer --inspect) on the kit's mutant labs: each
mutant's viewer (build/mutants/NAME, the mutant as the student's lab beside the reference
solutions) replays one pixel of the VI2 box, and the first divergence must be the mutant's bug,
checked by kind and handout step. The replay is exact (the same random numbers, no sampling
tolerance), so nothing here can fail by chance. The reference solutions submitted as a
student's labs must agree with themselves everywhere. Bad --inspect options exit 2 and write
nothing.
"""
import json
import os
import subprocess
import tempfile

from support import LABS, arguments, check, finish

args = arguments()
SCENE = os.path.join(args.source, "models", "cornell_box_VI2_Specular.ecs")
# A pixel of the left (red) wall: diffuse, lit, and its paths reach the mirror, the glass and
# the light within 16 samples.
PIXEL = ["30", "256"]

# mutant: (kind, step, words the sentence must hold)
EXPECTED = {
    "branching_emission_twice": ("emission", "lab1.1", "added the emission"),
    "branching_no_specular_emission": ("emission", "lab1.1", "did not add the emission"),
    "branching_depth_plus_one": ("depth", "lab1.2", "depth limit"),
    "branching_pi_kd": ("probability", "lab1.3", "diffuse ray"),
    "uniform_no_divide": ("probability", "lab2.4", "did not divide"),
    "uniform_nonblack_pick": ("pick", "lab2.3", "with the same random numbers"),
    "importance_wrong_probability": ("probability", "lab3.4", "the reference by 1"),
    "importance_luminance_pick": ("probability", "lab3.3", "probabilities are not the reference's"),
    "importance_no_nee": ("direct-light", "", "ctx.directLight"),
    "importance_reused_pick_number": ("draw-order", "", "cannot be compared"),
    "roulette_keeps_depth_limit": ("depth", "lab4.2", "a depth limit is still there"),
    "roulette_no_weight": ("probability", "lab4.4", "did not divide"),
    "uniform_own_random": ("draw-order", "", "cannot be compared"),
    "roulette_thread_local_engine": ("roulette", "lab4.2", "without a random number from ctx.sampler"),
}


def inspect(viewer, lab, out, extra=()):
    return subprocess.run([viewer, "-c", SCENE, "--lab", lab, "--continue-prob", "0.8",
                           "--inspect", *PIXEL, "--inspect-samples", "16", "--inspect-out", out,
                           *extra], capture_output=True, text=True, timeout=120)


def mutants_named(tmp):
    for name, (kind, step, words) in sorted(EXPECTED.items()):
        lab = name.split("_")[0]
        out = os.path.join(tmp, name + ".json")
        run = inspect(os.path.join(args.build, "mutants", name), lab, out)
        found = json.load(open(out))["comparison"] if run.returncode == 0 else {}
        d = found.get("divergence") or {}
        check(d.get("kind") == kind and d.get("step") == step and words in d.get("text", ""),
              f"the replay names {name}: {kind} at TODO {step or '(none)'}, saying '{words}'"
              + ("" if d.get("kind") == kind and d.get("step") == step
                 else f" (it said {d or run.stderr.strip()[-300:]})"))


def solutions_agree(tmp):
    for lab in LABS:
        out = os.path.join(tmp, "solutions-" + lab + ".json")
        run = inspect(os.path.join(args.build, "viewer_solutions_as_student"), lab, out)
        found = json.load(open(out)) if run.returncode == 0 else {}
        comparison = found.get("comparison", {})
        check(run.returncode == 0 and comparison.get("divergence") is None
              and comparison.get("comparable") is True and len(found["samples"]) == 16,
              f"the reference solution of {lab}, as a student's lab, agrees with itself on 16 samples")


def table_flags():
    """The table alone (the student release has no reference) flags an end or a bounce that the
    lab's own parameters forbid; the solutions' tables flag nothing."""
    def table(viewer, lab, *extra):
        return subprocess.run([viewer, "-c", SCENE, "--lab", lab, "--continue-prob", "0.8", "--inspect",
                               *PIXEL, "--inspect-samples", "16", *extra],
                              capture_output=True, text=True, timeout=120).stdout
    mutants = os.path.join(args.build, "mutants")
    check("ENDED without a random number drawn" in table(os.path.join(mutants, "roulette_keeps_depth_limit"), "roulette"),
          "the table flags a lab 4 path that ended without a roulette draw")
    check("WENT ON from depth 3 = maxDepth" in table(os.path.join(mutants, "branching_depth_plus_one"), "branching"),
          "the table flags a lab 1 bounce from depth maxDepth")
    flagged = [lab for lab in LABS
               if any(word in table(os.path.join(args.build, "viewer"), lab, "--solution") for word in ("ENDED", "WENT ON"))]
    check(not flagged, f"the solutions' tables flag nothing {flagged or ''}")


def bad_options(tmp):
    viewer = os.path.join(args.build, "viewer")
    out = os.path.join(tmp, "bad.json")
    cases = [
        (["--inspect", "512", "10"], "outside the 512x512 image"),
        (["--inspect", "10", "-1"], "outside"),
        (["--size", "64", "64", "--inspect", "64", "0"], "outside the 64x64 image"),
        (["--inspect-out", out], "needs --inspect"),
        (["--inspect", "10", "10", "--inspect-samples", "0"], "inspect-samples"),
        (["--inspect", "10", "10", "--inspect-out", os.path.join(tmp, "no", "such", "x.json")], "x.json"),
    ]
    for extra, words in cases:
        run = subprocess.run([viewer, "-c", SCENE, "--solution", *extra, "-o", os.path.join(tmp, "bad.exr")],
                             capture_output=True, text=True, timeout=60)
        written = [f for f in ("bad.json", "bad.exr") if os.path.exists(os.path.join(tmp, f))]
        check(run.returncode == 2 and words in run.stderr and len(run.stderr.strip().splitlines()) == 1
              and not written,
              f"viewer {' '.join(extra)}: one line naming '{words}', exit 2, nothing written"
              + ("" if run.returncode == 2 and words in run.stderr
                 else f" (exit {run.returncode}: {run.stderr.strip()[-200:]})"))


with tempfile.TemporaryDirectory(prefix="pathlab-replay-test-") as tmp:
    mutants_named(tmp)
    solutions_agree(tmp)
    table_flags()
    bad_options(tmp)
finish()
