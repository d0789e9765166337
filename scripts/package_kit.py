#!/usr/bin/env python3
"""The kit's two packages, made from this folder's files as they are.

Usage:
  package_kit.py student-release OUT.tar.gz [--rubric FILE --build BUILD [--references DIR]]
                                              the student release (docs/instructor-guide.md: The student release)
  package_kit.py gradescope OUT.zip           the Gradescope autograder (docs/instructor-guide.md: Gradescope)

The kit's files are those git tracks, as they are in the working tree (so a stray file of the
instructor's never ships); in a kit without git, every file but the build folders. The student
release is a copy of them minus STUDENT_EXCLUDED, under one top folder `pathlab/`, with no
history, and with README-student.md as its README.md. With --rubric, the release carries the
instructor's rubric as its grader/rubric.json (without its late policy and regrade setting,
which only a batch's gradebook uses, and without the name of its per-student variants' class
secret, which must not be a file the release would carry), the files of every public scene it
names (an instructor's own scene in models/ too, tracked or not), the stored references measured
again (by BUILD's grader and the reference solutions) for each public scene whose stored one does
not fit that rubric, and grader/release.json saying which rubric it is. The autograder holds every
file, solutions included, with scripts/gradescope/setup.sh and run_autograder at the root, as
Gradescope wants; a scene its rubric grades on that git does not track stops it.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tarfile
import tempfile
import time
import zipfile

KIT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# What the student release leaves out: everything that holds solution code (mutants and hostile
# labs are solutions with one change), the tests and tools that need it (they run only where
# solutions/ is), the instructor's hidden scenes, and what only instructors and maintainers use:
# their documents, the cluster and Gradescope scripts, the packaging itself.
STUDENT_EXCLUDED = (
    "solutions/",
    "tests/grader/mutants/",
    "tests/grader/mutants.json",
    "tests/grader/hostile/",
    "tests/grader/grader_test.py",
    "tests/grader/batch_test.py",
    "tests/grader/instructor_test.py",
    "tests/grader/pages_test.py",
    "tests/grader/support.py",
    "tests/estimators/catches_mutants.py",
    "tests/release/",
    "tests/gradescope/",
    "tests/bench/",
    "tests/viewer/",
    "tests/platforms/",
    "tests/docs/",
    "grader/hidden_scenes/",
    "grader/slurm/",
    "apps/bench/",
    "docs/",
    "handouts/tools/make_figures.py",
    "handouts/tools/make_inspector_figures.py",
    "handouts/tools/viewer_runs.py",
    "handouts/tools/pfm.py",
    "handouts/tools/convergence.gp",
    "handouts/tools/roulette_sweep.gp",
    "scripts/gradescope/",
    "scripts/package_kit.py",
    "scripts/virtual_display.py",
    "README.md",
)
# The students' README, which the release holds as README.md in place of the kit's.
STUDENT_README = "README-student.md"
RELEASE_FOLDER = "pathlab"
README_NAME = "README.md"


def kit_files(root=KIT):
    """The kit's files, relative to root, sorted."""
    try:
        listed = subprocess.run(
            ["git", "-C", root, "ls-files", "-z", "--cached"],
            capture_output=True, check=True).stdout.decode().split("\0")
        in_git = os.path.exists(os.path.join(root, ".git"))
    except (OSError, subprocess.CalledProcessError):
        listed, in_git = [], False
    if not in_git:
        listed = []
        for folder, subfolders, files in os.walk(root):
            relative = os.path.relpath(folder, root)
            subfolders[:] = [s for s in subfolders if not (
                s == ".git" or s == "__pycache__" or (relative == "." and
                                                      (s == "build" or s.startswith("build-"))))]
            listed += [os.path.normpath(os.path.join(relative, f)) for f in files]
    # A file deleted from the working tree but not from git's index is not part of the kit.
    return sorted(f for f in listed if f and os.path.isfile(os.path.join(root, f)))


# The instructor's hidden scenes: in the autograder whether git tracks them or not (they are
# often kept out of a repository students might see).
HIDDEN_SCENES = "grader/hidden_scenes/"


def hidden_scene_files(root=KIT):
    """The files under grader/hidden_scenes/, relative to root, sorted."""
    folder = os.path.join(root, HIDDEN_SCENES)
    found = []
    for path, _, files in os.walk(folder):
        found += [os.path.relpath(os.path.join(path, f), root) for f in files]
    return sorted(found)


def student_files(root=KIT):
    """{name in the release: file in the kit}, sorted by name."""
    files = {(README_NAME if f == STUDENT_README else f): f
             for f in kit_files(root) if not f.startswith(STUDENT_EXCLUDED)}
    return dict(sorted(files.items()))


def write_atomically(path, write):
    """Calls write(temporary path), then renames the result to path."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    temporary = path + ".tmp"
    try:
        write(temporary)
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)


def normalised(info):
    """Archive entries owned by nobody in particular, readable by all."""
    info.uid = info.gid = 0
    info.uname = info.gname = ""
    info.mode = 0o755 if info.mode & 0o111 else 0o644
    return info


RUBRIC = "grader/rubric.json"
REFERENCES = "grader/references/"
RELEASE_JSON = "grader/release.json"
GRADEBOOK_ONLY = ("late", "regrades")


class PackagingError(Exception):
    """A reason the package cannot be made, in one line; nothing is written."""


def rubric_named_files(rubric):
    """{what: absolute path} of the files the rubric at `rubric` names, relative to its folder:
    the class secret (variants.secret_file) and the late policy's extensions (late.extensions).
    Both are the instructor's: the secret keeps the variants, the extensions name students."""
    try:
        with open(rubric) as f:
            j = json.load(f)
    except (OSError, ValueError):
        return {}
    named = {}
    for what, section, key in (("the class secret", "variants", "secret_file"),
                               ("the late policy's extensions", "late", "extensions")):
        value = j.get(section, {}).get(key) if isinstance(j.get(section), dict) else None
        if isinstance(value, str) and value:
            named[what] = os.path.realpath(os.path.join(os.path.dirname(os.path.abspath(rubric)), value))
    return named


def refuse_shipping_named_files(files, rubric):
    """A student release must not carry the secret or the extensions the rubric names."""
    for what, path in rubric_named_files(rubric).items():
        shipped = [n for n, f in files.items() if os.path.realpath(f) == path]
        if shipped:
            raise PackagingError(f"{what} {path} is a file of the kit ({shipped[0]}) and would ship "
                                 "in the release: keep it outside the kit, or out of git")


def rubric_scene_files(grader, rubric, root):
    """{name in the release: file} of every public scene the rubric names (its .ecs, meshes and
    materials, as the grader reads them), whether git tracks them or not: an instructor's own
    scene, added to models/ for the course, goes with the rubric that grades on it."""
    listed = subprocess.run([grader, "rubric", "--rubric", rubric, "--scene-files"],
                            capture_output=True, text=True)
    if listed.returncode != 0:
        raise PackagingError(f"RUBRIC={rubric}: the grader cannot list its scenes: "
                             + listed.stderr.strip())
    files = {}
    for path in listed.stdout.splitlines():
        relative = os.path.relpath(os.path.realpath(path), os.path.realpath(root))
        if relative.startswith(".."):
            raise PackagingError(f"RUBRIC={rubric} grades on {path}, outside the kit: put the "
                                 "scene in models/")
        files[relative] = os.path.join(root, relative)
    return files


def instructor_rubric(rubric, build, scratch, root=KIT, stored=None):
    """{name in the release: file to pack} for the instructor's rubric: the rubric itself, the
    public scenes it names, the references that fit it (measured again where those `stored`,
    the instructor's folder of them, else the kit's, do not) and release.json; the grader of
    `build` checks the rubric and measures."""
    grader = os.path.abspath(os.path.join(build, "grader"))
    if not os.path.isfile(rubric):
        raise PackagingError(f"RUBRIC={rubric}: no such file")
    if not os.access(grader, os.X_OK):
        raise PackagingError(f"{grader} is not built (make build, or the grader target)")
    rubric = os.path.abspath(rubric)
    described = subprocess.run([grader, "rubric", "--rubric", rubric], capture_output=True, text=True)
    found = re.search(r"\(hash ([0-9a-f]+)\)", described.stdout)
    if described.returncode != 0 or not found:
        raise PackagingError(f"RUBRIC={rubric} is not a rubric the grader takes: "
                             + (described.stderr.strip() or described.stdout.strip()))
    references = os.path.join(scratch, "references")
    if stored and not os.path.isdir(stored):
        raise PackagingError(f"REFERENCES={stored}: no such folder")
    shutil.copytree(stored or os.path.join(KIT, REFERENCES), references)
    print(f"checking the stored references against {rubric} (a scene whose reference does not fit "
          "it is measured again from the reference solutions: a minute or more each)", flush=True)
    measured = subprocess.run([grader, "make-references", "--only-stale", "--rubric", rubric,
                               "--references", references], cwd=build)
    if measured.returncode != 0:
        raise PackagingError(f"measuring the references for {rubric} failed (exit {measured.returncode})")
    # The sections that only decide a batch's gradebook (a late policy, whose extensions file
    # names students; what a regrade may lower) stay with the instructor: both are outside the
    # rubric's hash, so the release's rubric keeps the hash the grader gave the instructor's.
    packed = json.load(open(rubric))
    for section in GRADEBOOK_ONLY:
        packed.pop(section, None)
    # Per-student variants: the class secret's file stays with the instructor, and so does its
    # name (outside the hash too); a student grades on their own variant folder instead.
    if isinstance(packed.get("variants"), dict):
        packed["variants"].pop("secret_file", None)
    packed_rubric = os.path.join(scratch, "rubric.json")
    with open(packed_rubric, "w") as f:
        json.dump(packed, f, indent=1)
        f.write("\n")
    release = os.path.join(scratch, "release.json")
    with open(release, "w") as f:
        json.dump({"rubric": os.path.basename(rubric), "rubric_hash": found.group(1),
                   "packaged_at": time.strftime("%Y-%m-%dT%H:%MZ", time.gmtime())}, f, indent=1)
        f.write("\n")
    files = {RUBRIC: packed_rubric, RELEASE_JSON: release}
    files.update(rubric_scene_files(grader, rubric, root))
    for name in sorted(os.listdir(references)):
        files[REFERENCES + name] = os.path.join(references, name)
    return files, found.group(1)


def student_release(out, root=KIT, rubric=None, build=None, references=None):
    files = {name: os.path.join(root, f) for name, f in student_files(root).items()}
    with tempfile.TemporaryDirectory() as scratch:
        # Whichever rubric the release carries, what it names for the instructor stays behind.
        refuse_shipping_named_files(files, rubric or os.path.join(root, RUBRIC))
        if rubric:
            instructors, rubric_hash = instructor_rubric(rubric, build, scratch, root, references)
            untracked = sorted(n for n in instructors if n.startswith("models/") and n not in files)
            files = {n: f for n, f in files.items() if n != RUBRIC and not n.startswith(REFERENCES)}
            files.update(instructors)
            files = dict(sorted(files.items()))
            if untracked:
                print("packed the rubric's scene files that git does not track: " + ", ".join(untracked))

        def write(path):
            with tarfile.open(path, "w:gz") as tar:
                for name, f in files.items():
                    tar.add(f, arcname=f"{RELEASE_FOLDER}/{name}", recursive=False, filter=normalised)

        write_atomically(out, write)
    if rubric:
        print(f"the release carries the rubric {rubric} (hash {rubric_hash}); "
              "its students' grader rubric and make grade say so")
    return files


def rubric_files_for_autograder(root):
    """The files grader/rubric.json names (the class secret, the extensions), relative to the
    kit, for the autograder, which needs them and which students never see, whether git tracks
    them or not. One outside the kit, or missing, stops the packaging: the autograder would stop
    every grading without it."""
    found = []
    for what, path in rubric_named_files(os.path.join(root, RUBRIC)).items():
        relative = os.path.relpath(path, os.path.realpath(root))
        if relative.startswith(".."):
            raise PackagingError(f"{RUBRIC} names {what} {path}, outside the kit: the autograder "
                                 "would not have it; put it beside the rubric in grader/ (git may "
                                 "ignore it)")
        if not os.path.isfile(path):
            raise PackagingError(f"{RUBRIC} names {what} {relative}, which does not exist")
        found.append(relative)
    return found


def rubric_scene_names(rubric):
    """The public scenes a rubric names, by name in models/ (the grader's Rubric reads the same
    keys): its correctness scenes, its noise and speed scenes, its variants' box."""
    try:
        with open(rubric) as f:
            j = json.load(f)
    except (OSError, ValueError):
        return []
    section = lambda name: j.get(name) if isinstance(j.get(name), dict) else {}
    names = list(section("correctness").get("scenes", []))
    names += [section("noise").get("scene"), section("speed").get("scene"),
              (section("variants").get("box") or {}).get("scene")]
    return sorted({n for n in names if isinstance(n, str) and n})


def require_rubric_scenes(files, root):
    """The autograder holds the kit's tracked files: a scene the rubric grades on that git does
    not track would stop every grading there, so it stops the packaging instead."""
    for name in rubric_scene_names(os.path.join(root, RUBRIC)):
        if f"models/{name}.ecs" not in files:
            raise PackagingError(f"{RUBRIC} grades on {name}, but git does not track "
                                 f"models/{name}.ecs: the autograder would not have it; "
                                 f"git add models/{name}.* (its .obj and .mtl too)")


def gradescope(out, root=KIT):
    files = sorted(set(kit_files(root)) | set(hidden_scene_files(root))
                   | set(rubric_files_for_autograder(root)))
    require_rubric_scenes(files, root)
    at_root = {name: os.path.join(root, "scripts", "gradescope", name)
               for name in ("setup.sh", "run_autograder")}

    def add(archive, source, name):
        info = zipfile.ZipInfo.from_file(source, name)
        executable = os.stat(source).st_mode & 0o111
        info.external_attr = ((0o100755 if executable else 0o100644) << 16)
        with open(source, "rb") as f:
            archive.writestr(info, f.read(), zipfile.ZIP_DEFLATED)

    def write(path):
        with zipfile.ZipFile(path, "w") as archive:
            for name, source in at_root.items():
                add(archive, source, name)
            for f in files:
                if f not in at_root:
                    add(archive, os.path.join(root, f), f)

    write_atomically(out, write)
    return files


def main(argv):
    options = dict(zip(argv[3::2], argv[4::2]))
    if (len(argv) < 3 or argv[1] not in ("student-release", "gradescope") or len(argv) % 2 == 0
            or set(options) - {"--rubric", "--build", "--references"}
            or ("--rubric" in options) != ("--build" in options)
            or ("--references" in options and "--rubric" not in options)
            or (options and argv[1] != "student-release")):
        print(__doc__.strip().split("\n\n")[1], file=sys.stderr)
        return 2
    command, out = argv[1], argv[2]
    if not os.path.isdir(os.path.join(KIT, "solutions")):
        print(f"package_kit.py: {KIT} has no solutions/: {command} is made from the instructor's "
              "kit, not from the student release", file=sys.stderr)
        return 2
    try:
        files = (student_release(out, rubric=options.get("--rubric"), build=options.get("--build"),
                                 references=options.get("--references"))
                 if command == "student-release" else gradescope(out))
    except PackagingError as e:
        print(f"make {command}: {e}; nothing was written", file=sys.stderr)
        return 2
    size = os.path.getsize(out)
    print(f"{out}: {len(files)} files, {size / 1e6:.1f} MB")
    if command == "gradescope":
        hidden = [f for f in files if f.startswith(HIDDEN_SCENES)]
        scenes = [f for f in hidden if f.endswith(".ecs")]
        print(f"hidden scenes packed: {len(scenes)}" + "".join(f"\n  {f}" for f in hidden)
              if hidden else "hidden scenes packed: none (grader/hidden_scenes/ holds no file)")
        named = rubric_files_for_autograder(KIT)
        if named:
            print("packed for the autograder, as grader/rubric.json names them (instructor-only: "
                  "the autograder is never the students'): " + ", ".join(named))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
