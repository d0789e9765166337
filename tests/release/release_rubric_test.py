#!/usr/bin/env python3
"""A student release that carries the instructor's rubric (make student-release RUBRIC=FILE):
ctest `release.rubric`.

Usage: release_rubric_test.py --source KIT --build BUILD

Packages the kit with an instructor's rubric (the kit's, its points changed, its correctness
checked at 32x32 pixels on the furnace, the VI2 box (still its noise scene) and a scene of the
instructor's, and its speed timed on the furnace, so that those scenes' stored references no
longer fit and are measured again, and lab_figures.json's timed runs too) by scripts/package_kit.py, as the make target does, with BUILD's grader,
and checks, each printing PASS/FAIL:
- the release's grader/rubric.json is the instructor's, but the sections only a batch's
  gradebook uses (its late policy, whose extensions file names students, and its regrade
  setting; both outside the rubric's hash), and its grader/release.json names it with the hash
  the grader gives the instructor's file;
- the furnace's reference was measured again, at the rubric's size, and the references of the
  scenes it does not grade on are the kit's, unchanged; lab_figures.json's timed runs, of other
  runs than the rubric's, were measured again, so that the release's make grade can estimate
  speed, and its notebook figures (of the same noise scene) are the kit's;
- `grader rubric` on the release's rubric, beside its release.json, says which rubric the release
  carries; edited afterwards, it says it is not that one;
- an instructor's own public scene, added to models/ for the course and not tracked by git, is
  packed with its mesh and materials (and its reference measured), since the rubric grades on it;
- a rubric with per-student variants is packed without the name of its class secret's file
  (outside the hash, which stays the instructor's), and a secret that is a file of the kit stops
  the packaging, naming it;
- packaged again from the instructor's own references (REFERENCES=, here the first release's,
  which fit the rubric), nothing is measured again;
- a rubric naming a public scene not in models/ is refused by grader rubric and stops the
  packaging before anything is measured;
- a rubric the grader refuses (a lab's points missing) stops the packaging in one line naming
  the problem, exit 2, and no package is written.
"""
import argparse
import filecmp
import json
import os
import subprocess
import sys
import tarfile
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import check, exit_code  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--source", required=True)
parser.add_argument("--build", required=True)
args = parser.parse_args()
KIT, BUILD = os.path.abspath(args.source), os.path.abspath(args.build)
GRADER = os.path.join(BUILD, "grader")


def package(out, rubric, references=None):
    return subprocess.run([sys.executable, os.path.join(KIT, "scripts", "package_kit.py"), "student-release",
                           out, "--rubric", rubric, "--build", BUILD,
                           *(["--references", references] if references else [])], capture_output=True, text=True)


def course_scene(stem):
    """An instructor's own scene in the kit's models/, untracked: the diffuse box with a warmer
    light, its .ecs, .obj and .mtl named `stem`. Returns the files written."""
    models = os.path.join(KIT, "models")
    written = []
    for extension, rewrite in ((".ecs", lambda t: t.replace("cornell_box_diffuse.obj", stem + ".obj")),
                               (".obj", lambda t: t.replace("cornell_box_diffuse.mtl", stem + ".mtl")),
                               (".mtl", lambda t: t + "\nnewmtl unused_by_the_mesh\nKd 0.5 0.5 0.5\n")):
        with open(os.path.join(models, "cornell_box_diffuse" + extension)) as f:
            text = rewrite(f.read())
        path = os.path.join(models, stem + extension)
        with open(path, "w") as f:
            f.write(text)
        written.append(path)
    return written


def main():
    # Removed whatever happens: the scene is the test's, in the kit's folder for the grader to read.
    stem = f"course_box_{os.getpid()}"
    written = course_scene(stem)
    try:
        return checks(stem)
    finally:
        for path in written:
            os.remove(path)


def checks(stem):
    with tempfile.TemporaryDirectory() as root:
        rubric = json.load(open(os.path.join(KIT, "grader", "rubric.json")))
        rubric["about"] = "CS 999, fall 2026"
        rubric["points"]["uniform"]["noise"] = 4
        rubric["correctness"].update({"width": 32, "height": 32, "tiles": 2, "seeds": 4,
                                      "scenes": ["furnace", "cornell_box_VI2_Specular", stem]})
        rubric["speed"]["scene"] = "furnace"
        # The gradebook's own sections, the extensions file naming students: not for the release.
        rubric["late"] = {"penalty_per_day": 0.1, "extensions": "extensions.csv"}
        rubric["regrades"] = {"lower_scores": "keep_higher"}
        with open(os.path.join(root, "extensions.csv"), "w") as f:
            f.write("id,days\nerin,2\n")
        # Per-student variants: the secret's file, outside the kit, is the instructor's alone.
        rubric["variants"] = {"per_student": True, "secret_file": "class-secret.txt",
                              "furnace": {"albedo": [0.3, 0.7]}}
        with open(os.path.join(root, "class-secret.txt"), "w") as f:
            f.write("the course's own secret, 2026\n")
        course = os.path.join(root, "course-rubric.json")
        json.dump(rubric, open(course, "w"), indent=1)
        out = os.path.join(root, "release.tar.gz")
        made = package(out, course)
        print(made.stdout + made.stderr)
        check(made.returncode == 0 and "the release carries the rubric" in made.stdout,
              f"packaged with the instructor's rubric (exit {made.returncode})")
        if made.returncode != 0:
            return exit_code()
        unpacked = os.path.join(root, "unpacked")
        with tarfile.open(out) as tar:
            tar.extractall(unpacked)
        grader_folder = os.path.join(unpacked, "pathlab", "grader")
        release = json.load(open(os.path.join(grader_folder, "release.json")))
        described = subprocess.run([GRADER, "rubric", "--rubric", course], capture_output=True, text=True).stdout
        packed = json.load(open(os.path.join(grader_folder, "rubric.json")))
        expected = {k: v for k, v in rubric.items() if k not in ("late", "regrades")}
        expected["variants"] = {k: v for k, v in rubric["variants"].items() if k != "secret_file"}
        check(packed == expected and release["rubric"] == "course-rubric.json"
              and f"(hash {release['rubric_hash']})" in described
              and not os.path.exists(os.path.join(grader_folder, "extensions.csv"))
              and not os.path.exists(os.path.join(grader_folder, "class-secret.txt")),
              "the release's rubric is the instructor's, but its late policy and regrade setting (the gradebook's, "
              f"naming students) and its class secret's name, and release.json names it and its hash ({release})")
        furnace = json.load(open(os.path.join(grader_folder, "references", "furnace.json")))
        kit_glass = os.path.join(KIT, "grader", "references", "refraction_check.json")
        check(furnace["width"] == 32 and filecmp.cmp(os.path.join(grader_folder, "references",
                                                                    "refraction_check.json"),
                                                       kit_glass, shallow=False)
              and "measuring furnace again" in made.stdout,
              f"the furnace's reference measured again at 32x32 (width {furnace['width']}), the glass's, "
              "a scene the rubric does not grade on, kept as the kit's")
        figures = json.load(open(os.path.join(grader_folder, "references", "lab_figures.json")))
        kit_figures = json.load(open(os.path.join(KIT, "grader", "references", "lab_figures.json")))
        timed = figures["timed_runs"]
        check("measuring lab_figures.json's timed runs again" in made.stdout
              and (timed["scene"], timed["width"], timed["seeds"]) == ("furnace", 32, 4)
              and all(v > 0 for v in timed["samples_per_second"].values()) and "machine" in timed
              and figures["notebook"] == kit_figures["notebook"],
              "lab_figures.json's timed runs measured again on the rubric's runs for the release "
              f"({timed['scene']}, {timed['width']}x{timed['height']}, {timed['seeds']} seeds), its notebook kept")
        course_files = [f"models/{stem}{e}" for e in (".ecs", ".obj", ".mtl")]
        check(all(os.path.isfile(os.path.join(unpacked, "pathlab", f)) for f in course_files)
              and os.path.isfile(os.path.join(grader_folder, "references", stem + ".json"))
              and f"models/{stem}.ecs" in made.stdout and "git does not track" in made.stdout,
              f"the instructor's own scene {stem}, untracked, is packed with its mesh, materials and reference")
        released = os.path.join(grader_folder, "rubric.json")
        says = subprocess.run([GRADER, "rubric", "--rubric", released], capture_output=True, text=True).stdout
        check(f"this release carries the instructor's rubric course-rubric.json (hash {release['rubric_hash']})" in says
              and "is not that rubric" not in says, "grader rubric in the release says which rubric it carries")
        edited = json.load(open(released))
        edited["points"]["uniform"]["noise"] = 40
        json.dump(edited, open(released, "w"))
        says = subprocess.run([GRADER, "rubric", "--rubric", released], capture_output=True, text=True).stdout
        check("is not that rubric" in says and "may differ from your instructor's" in says,
              "an edited rubric in the release is told apart from the instructor's")

        # Packaged from the instructor's own references, which fit: nothing is measured again.
        again = package(os.path.join(root, "again.tar.gz"), course, os.path.join(grader_folder, "references"))
        check(again.returncode == 0 and "measuring" not in again.stdout
              and "kept" in again.stdout and f"{stem}.json: it fits" in again.stdout,
              f"packaged from REFERENCES= that fit the rubric, nothing measured again (exit {again.returncode})")

        # A public scene that is not in models/: refused at once, before any measuring.
        nowhere = dict(rubric, correctness=dict(rubric["correctness"], scenes=["furnace", "nowhere_box"]))
        nowhere_rubric = os.path.join(root, "nowhere.json")
        json.dump(nowhere, open(nowhere_rubric, "w"))
        said = subprocess.run([GRADER, "rubric", "--rubric", nowhere_rubric], capture_output=True, text=True)
        refused = package(os.path.join(root, "nowhere.tar.gz"), nowhere_rubric)
        check(said.returncode == 2 and "public scene 'nowhere_box'" in said.stderr
              and refused.returncode == 2 and "public scene 'nowhere_box'" in refused.stderr
              and "measuring" not in refused.stdout,
              f"a rubric naming a scene not in models/ is refused before any measuring ({said.stderr.strip()})")

        # A class secret that git tracks in the kit would ship in the release: refused.
        tracked = dict(rubric, variants=dict(rubric["variants"], secret_file=os.path.join(KIT, "models", "furnace.mtl")))
        tracked_rubric = os.path.join(root, "tracked-secret.json")
        json.dump(tracked, open(tracked_rubric, "w"))
        tracked_out = os.path.join(root, "tracked.tar.gz")
        refused = package(tracked_out, tracked_rubric)
        check(refused.returncode == 2 and "would ship in the release" in refused.stderr
              and "models/furnace.mtl" in refused.stderr and not os.path.exists(tracked_out),
              f"a class secret that is a file of the kit stops the packaging ({refused.stderr.strip()[-200:]})")

        # The autograder packs the kit's tracked files: a rubric grading on an untracked scene
        # stops `make gradescope` (checked on a kit of the rubric alone).
        sys.path.insert(0, os.path.join(KIT, "scripts"))
        import package_kit
        gradescope_kit = os.path.join(root, "gradescope-kit")
        os.makedirs(os.path.join(gradescope_kit, "grader"))
        json.dump(rubric, open(os.path.join(gradescope_kit, "grader", "rubric.json"), "w"))
        tracked_scenes = ["models/furnace.ecs", "models/cornell_box_VI2_Specular.ecs"]
        try:
            package_kit.require_rubric_scenes(tracked_scenes, gradescope_kit)
            words = ""
        except package_kit.PackagingError as error:
            words = str(error)
        check(f"grades on {stem}, but git does not track models/{stem}.ecs" in words,
              f"make gradescope refuses a rubric grading on an untracked scene ({words})")

        del rubric["points"]["mis"]
        broken = os.path.join(root, "broken.json")
        json.dump(rubric, open(broken, "w"))
        refused_out = os.path.join(root, "refused.tar.gz")
        refused = package(refused_out, broken)
        lines = refused.stderr.strip().splitlines()
        check(refused.returncode == 2 and len(lines) == 1 and "broken.json" in lines[0] and "\"mis\"" in lines[0]
              and "nothing was written" in lines[0] and not os.path.exists(refused_out),
              f"a rubric without lab 6's points: one line naming it, exit 2, no package ({refused.stderr.strip()})")
    return exit_code()


if __name__ == "__main__":
    sys.exit(main())
