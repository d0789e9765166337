#!/usr/bin/env python3
"""The pick test (viewer --pick-test) on the kit's solutions and mutant labs: on mixed_surfaces,
whose red diffuse components sit beside teal mirrors and cyan glass, a lab that picks a
component with one probability and divides by another must fail, named by the material and the
two numbers; the solutions and the mutants that pick by another rule but divide by that rule's
probability must pass (they are consistent, and their images unbiased); a branching lab has
nothing to test. Each run is a chi-square test per material at a combined false-fail rate of
0.001 on a fixed grid of pixels and seeds, so its verdict does not change from run to run.
"""
import os
import re
import subprocess

from support import arguments, check, finish

args = arguments()
SCENE = os.path.join(args.source, "models", "mixed_surfaces.ecs")

# viewer (build/NAME): (lab, passes, words the verdict holds)
EXPECTED = {
    "viewer_solutions_as_student": [("uniform", True, "passed"), ("importance", True, "passed"),
                                    ("roulette", True, "passed"),
                                    ("branching", True, "nothing to test")],
    "mutants/importance_luminance_pick": [("importance", True, "passed")],
    "mutants/roulette_average_pick": [("roulette", True, "passed")],
    "mutants/uniform_nonblack_pick": [("uniform", True, "passed")],
    "mutants/importance_luminance_pick_max_divide": [
        ("importance", False, r"at Kd 0\.8,0\.1,0\.02 Ks 0\.05,0\.45,0\.3 \(\d+ visits\) you went "
                              r"on by mirror with frequency 0\.5\d+ and divided by 0\.36")],
    "mutants/importance_wrong_probability": [("importance", False, "divided by 0.333")],
    "mutants/uniform_half_probability": [("uniform", False, "divided by 0.5")],
    "mutants/uniform_no_divide": [("uniform", False, "divided by 1")],
    "mutants/roulette_no_weight": [("roulette", False, "divided by 1")],
}

for viewer, runs in EXPECTED.items():
    for lab, passes, words in runs:
        run = subprocess.run([os.path.join(args.build, viewer), "-c", SCENE, "--lab", lab,
                              "--continue-prob", "0.8", "--size", "64", "64", "--pick-test"],
                             capture_output=True, text=True, timeout=300)
        said = run.stdout + run.stderr
        status = 0 if passes else 1
        check(run.returncode == status and re.search(words, said) is not None,
              f"{viewer} --lab {lab} --pick-test: exit {status} with /{words}/" +
              ("" if run.returncode == status and re.search(words, said)
               else f"; it exited {run.returncode} and said:\n{said[-1500:]}"))

finish()
