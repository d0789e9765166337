#!/usr/bin/env python3
"""The grader's speed check compares a lab with the reference solution built the same way
(README, Performance). Two places must keep it so, and this test fails when either does not:

1. In a build, the student's labs and the solutions are compiled with the same code-generation
   flags: `make grade` times the one against the other in one viewer.
2. `grader batch` compiles the solutions' library and every submission from the one flag list of
   lab_library_build.json (grader/src/isolation/lab_library.cpp); its code-generation flags must
   be the build's own, so that a ratio a student measures with `make grade` and the one the
   instructor's batch measures compare like with like. (Link-time optimisation of the viewer
   alone, for one, would break this: a lab loaded from a library cannot be optimised with the
   framework that calls it.)

A control first: the comparison must notice a flag added to one side.

Usage: same_build_test.py --build BUILD
"""
import argparse
import json
import os
import shlex
import sys

# Flags that change the code a lab compiles to, and so its speed. Others (warnings, include
# folders, defines, -fPIC and visibility for a shared library, sanitizers, which a submission is
# never built with) do not take part.
CODE_FLAGS = ("-O", "-march", "-mtune", "-mcpu", "-flto", "-ffp-contract", "-ffast-math",
              "-fno-math-errno", "-funsafe-math", "-fprofile", "-funroll", "-std=")


def code_flags(arguments):
    return sorted(a for a in arguments if a.startswith(CODE_FLAGS))


def lab_objects(build, target):
    """{lab file name: its code flags} for the lab files compiled into `target`."""
    with open(os.path.join(build, "compile_commands.json")) as f:
        commands = json.load(f)
    found = {}
    for entry in commands:
        arguments = entry.get("arguments") or shlex.split(entry["command"])
        output = arguments[arguments.index("-o") + 1] if "-o" in arguments else ""
        if f"/{target}.dir/" in "/" + output:
            found[os.path.basename(entry["file"])] = code_flags(arguments)
    return found


def differences(a, b):
    return sorted(set(a) ^ set(b))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", required=True)
    build = parser.parse_args().build

    # The control: a flag on one side alone is a difference.
    base = ["-O3", "-march=native", "-ffp-contract=off", "-std=c++17", "-Wall", "-DX=1"]
    if differences(code_flags(base), code_flags(base + ["-flto=auto", "-Wextra"])) != ["-flto=auto"]:
        sys.exit("the comparison does not notice -flto on one side")

    student = lab_objects(build, "pathlab_student")
    solutions = lab_objects(build, "pathlab_solution")
    labs = sorted(f for f in student if f != "lab_table.cpp")
    if not labs or sorted(f for f in solutions if f != "lab_table.cpp") != labs:
        sys.exit(f"lab files: student {sorted(student)}, solutions {sorted(solutions)}")
    for lab in labs:
        if differences(student[lab], solutions[lab]):
            sys.exit(f"labs/{lab} and solutions/{lab} are compiled differently: "
                     f"{differences(student[lab], solutions[lab])} (make grade would time one "
                     "against the other)")
    viewer_flags = student[labs[0]]
    print(f"the build's labs and solutions: {' '.join(viewer_flags)}")

    description = os.path.join(build, "lab_library_build.json")
    if not os.path.exists(description):
        print("no lab_library_build.json (a build without the sandbox has no grader batch)")
        return
    with open(description) as f:
        batch_flags = code_flags(json.load(f)["flags"])
    if differences(batch_flags, viewer_flags):
        sys.exit(f"grader batch compiles labs with {' '.join(batch_flags)}, the build with "
                 f"{' '.join(viewer_flags)}: differences {differences(batch_flags, viewer_flags)}")
    print(f"grader batch's submissions and solutions: {' '.join(batch_flags)}: the same")


if __name__ == "__main__":
    main()
