#!/usr/bin/env python3
"""Runs inside the grader's sandbox: finds a submission's lab files and copies them, and
nothing else, to the scratch folder.

    unpack_submission.py SUBMISSION MAX_BYTES LAB_FILE...

SUBMISSION is a folder, a .zip, a .tar.gz/.tgz/.tar, or a git repository (a folder holding
.git, or a bare repository): for a repository, the files of its HEAD commit, read as blobs
from its object store (GitObjects: none of its configuration, attributes, filters or hooks).
Only regular files named as one of the LAB_FILEs (the grader passes the lab list's files:
branching.cpp, uniform.cpp, importance.cpp, roulette.cpp) are taken, each at most MAX_BYTES; symbolic links, devices and everything else are skipped and never followed. Where a
name occurs more than once, the copy in a folder named `labs` wins, then the shallowest; two
equally good copies are ambiguous and neither is taken.

Writes the files taken to ./NAME and a report to ./intake.json:
    {"kind": "...", "taken": {name: path}, "problems": ["..."]}
"""
import json
import os
import re
import stat
import subprocess
import sys
import tarfile
import time
import zipfile

MAX_ENTRIES = 20000  # members or folder entries looked at, at most


class Candidates:
    """Every acceptable copy of each lab file seen, with a way to read it."""

    def __init__(self, limit, lab_files):
        self.limit = limit
        self.found = {name: [] for name in lab_files}
        self.problems = []

    def offer(self, path, size, is_regular, read):
        name = path.replace("\\", "/").rsplit("/", 1)[-1]
        if name not in self.found:
            return
        if not is_regular:
            self.problems.append(f"{path}: not a regular file (a link or a device?): skipped")
        elif size > self.limit:
            self.problems.append(f"{path}: {size} bytes, more than the {self.limit} allowed: skipped")
        else:
            self.found[name].append((path, read))

    def choose(self):
        taken = {}
        for name, copies in self.found.items():
            if not copies:
                continue

            def rank(copy):
                parts = copy[0].replace("\\", "/").strip("/").split("/")
                return (0 if len(parts) > 1 and parts[-2] == "labs" else 1, len(parts))

            copies.sort(key=rank)
            if len(copies) > 1 and rank(copies[0]) == rank(copies[1]):
                self.problems.append(f"{name}: found at {copies[0][0]} and {copies[1][0]}; "
                                     "which one is meant? Neither was taken")
                continue
            data = copies[0][1]()
            if data is None or len(data) > self.limit:
                self.problems.append(f"{copies[0][0]}: could not be read within the size limit")
                continue
            with open(name, "wb") as out:
                out.write(data)
            taken[name] = copies[0][0]
        return taken


def bounded(reader, limit):
    return reader.read(limit + 1)


def from_folder(root, candidates):
    seen = 0
    for folder, subfolders, files in os.walk(root, followlinks=False):
        subfolders[:] = [d for d in subfolders if d != ".git"]
        for name in files:
            seen += 1
            if seen > MAX_ENTRIES:
                candidates.problems.append(f"more than {MAX_ENTRIES} files: the rest were not looked at")
                return
            path = os.path.join(folder, name)
            info = os.lstat(path)
            regular = stat.S_ISREG(info.st_mode)

            def read(path=path):
                with open(path, "rb", opener=lambda p, f: os.open(p, f | os.O_NOFOLLOW)) as f:
                    return bounded(f, candidates.limit)

            candidates.offer(os.path.relpath(path, root), info.st_size, regular, read)


def from_zip(path, candidates):
    with zipfile.ZipFile(path) as archive:
        for i, member in enumerate(archive.infolist()):
            if i >= MAX_ENTRIES:
                candidates.problems.append(f"more than {MAX_ENTRIES} members: the rest were not looked at")
                break
            mode = member.external_attr >> 16
            # No file type at all (a zip written by a program that stores permissions alone,
            # as Python's writestr does) is a plain file; a link or a device has its type.
            regular = not member.is_dir() and (stat.S_IFMT(mode) == 0 or stat.S_ISREG(mode))

            def read(member=member):
                with archive.open(member) as f:
                    return bounded(f, candidates.limit)

            candidates.offer(member.filename, member.file_size, regular, read)
        return candidates.choose()


def from_tar(fileobj, candidates):
    with tarfile.open(fileobj=fileobj, mode="r:*") as archive:
        for i, member in enumerate(archive):
            if i >= MAX_ENTRIES:
                candidates.problems.append(f"more than {MAX_ENTRIES} members: the rest were not looked at")
                break

            def read(member=member):
                f = archive.extractfile(member)
                return bounded(f, candidates.limit) if f else None

            candidates.offer(member.name, member.size, member.isreg(), read)
        return candidates.choose()


GIT_OBJECT_ID = re.compile(r"[0-9a-f]{40}([0-9a-f]{24})?")


def git_dir_of(repository):
    """The repository's git folder: its .git, or the repository itself when bare."""
    dot_git = os.path.join(repository, ".git")
    if os.path.isdir(dot_git) and not os.path.islink(dot_git):
        return dot_git
    if os.path.lexists(dot_git):
        raise ValueError(".git is not a folder (a worktree or a submodule points elsewhere): "
                         "submit the repository itself")
    return repository


def read_small(path, limit=65536, inside=None):
    """A file's text, never through a link, not even a linked folder on its way when `inside`
    (the folder it must be in) is given; None if there is none."""
    if inside is not None and not os.path.realpath(path).startswith(
            os.path.realpath(inside) + os.sep):
        return None
    try:
        with open(path, "rb", opener=lambda p, f: os.open(p, f | os.O_NOFOLLOW)) as f:
            return f.read(limit).decode("utf-8", errors="replace")
    except OSError:
        return None


def resolve_head(git_dir):
    """HEAD's commit, read from the repository's files as git would (a symbolic ref, a loose ref
    or packed-refs): no git command runs in the submission's repository."""
    name = "HEAD"
    for _ in range(5):
        text = read_small(os.path.join(git_dir, name), inside=git_dir)
        if text is None and name.startswith("refs/"):
            packed = read_small(os.path.join(git_dir, "packed-refs"), 16 << 20, inside=git_dir)
            for line in (packed or "").splitlines():
                words = line.split()
                if len(words) == 2 and words[1] == name:
                    text = words[0]
                    break
        if text is None:
            raise ValueError(f"git could not read its HEAD commit: {name} is missing")
        text = text.strip()
        if text.startswith("ref: "):
            name = text[5:].strip()
            if not name.startswith("refs/") or ".." in name.split("/"):
                raise ValueError(f"git could not read its HEAD commit: HEAD names '{name}'")
            continue
        if GIT_OBJECT_ID.fullmatch(text):
            return text
        raise ValueError(f"git could not read its HEAD commit: {name} holds '{text[:60]}'")
    raise ValueError("git could not read its HEAD commit: symbolic references go round")


class GitObjects:
    """The objects of a submission's repository, read by git as plain data: git runs in a fresh,
    empty repository of our own whose object store is the submission's, so that nothing of the
    submission's configuration, attributes, filters or hooks is read, let alone run. Nor are the
    object store's own hints, which the student writes as freely: a commit-graph (whose trees
    could differ from the commits') is not read, and alternates are refused. Only the list of
    shallow commits is taken over, which can only make a lab's time later (an honest shallow
    clone's history stops there, and git log would fail on the missing parents)."""

    def __init__(self, repository):
        self.git_dir = git_dir_of(repository)
        # Its objects are read where they are: a linked folder could lead git out of it.
        objects = os.path.join(self.git_dir, "objects")
        if os.path.realpath(objects) != os.path.join(os.path.realpath(self.git_dir), "objects"):
            raise ValueError("the repository's objects folder is a link: submit the repository "
                             "itself")
        if os.path.lexists(os.path.join(objects, "info", "alternates")):
            raise ValueError("the repository borrows objects from another (objects/info/"
                             "alternates): submit a full clone")
        own = os.path.abspath("git-reader")
        for folder in ("objects", "refs"):
            os.makedirs(os.path.join(own, folder), exist_ok=True)
        with open(os.path.join(own, "HEAD"), "w") as f:
            f.write("ref: refs/heads/none\n")
        shallow = read_small(os.path.join(self.git_dir, "shallow"), 1 << 20, inside=self.git_dir)
        if shallow is not None:
            ids = shallow.split()
            if not all(GIT_OBJECT_ID.fullmatch(i) for i in ids):
                raise ValueError("git could not read the repository: its shallow file is not a "
                                 "list of commits")
            with open(os.path.join(own, "shallow"), "w") as f:
                f.write("".join(i + "\n" for i in ids))
        self.environment = {"PATH": os.environ.get("PATH", "/usr/bin:/bin"), "HOME": os.getcwd(),
                            "GIT_DIR": own,
                            "GIT_OBJECT_DIRECTORY": os.path.join(self.git_dir, "objects"),
                            "GIT_CONFIG_NOSYSTEM": "1", "GIT_CONFIG_GLOBAL": os.devnull,
                            "GIT_ATTR_NOSYSTEM": "1", "GIT_NO_REPLACE_OBJECTS": "1",
                            "GIT_TERMINAL_PROMPT": "0", "GIT_LITERAL_PATHSPECS": "1",
                            "GIT_CONFIG_COUNT": "1", "GIT_CONFIG_KEY_0": "core.commitGraph",
                            "GIT_CONFIG_VALUE_0": "false", "LC_ALL": "C"}

    def git(self, *arguments, timeout=60):
        run = subprocess.run(["git", *arguments], capture_output=True, timeout=timeout, env=self.environment)
        if run.returncode != 0:
            raise ValueError("git could not read the repository: "
                             + run.stderr.decode(errors="replace").strip()[:200])
        return run.stdout

    def head(self):
        """HEAD's commit: what HEAD names, a tag peeled; a HEAD naming a tree or a blob is no
        commit, and has no time."""
        named = resolve_head(self.git_dir)
        try:
            return self.git("rev-parse", "--verify", "--quiet", named + "^{commit}").decode().strip()
        except ValueError:
            raise ValueError(f"HEAD names {named}, which is not a commit") from None

    def head_files(self, candidates):
        """Offers every file of HEAD's tree to `candidates`, each read as a blob (no filter).
        A path git itself would not write (a component '.', '..' or empty, or not UTF-8) is
        skipped: git log's pathspec would read it as another path."""
        commit = self.head()
        listing = self.git("ls-tree", "-r", "-l", "-z", "--full-tree", commit)
        for i, entry in enumerate(listing.split(b"\0")):
            if not entry:
                continue
            if i >= MAX_ENTRIES:
                candidates.problems.append(f"more than {MAX_ENTRIES} files: the rest were not looked at")
                break
            meta, _, path = entry.partition(b"\t")
            mode, kind, object_id, size = meta.split()
            regular = kind == b"blob" and mode in (b"100644", b"100755")
            try:
                path.decode("utf-8")
                odd = any(part in (b"", b".", b"..") for part in path.split(b"/"))
            except UnicodeDecodeError:
                odd = True
            if odd:
                candidates.problems.append(f"{path.decode(errors='replace')!r}: a path git does "
                                           "not write (a '.', '..' or empty part, or not UTF-8): "
                                           "skipped")
                continue

            def read(object_id=object_id.decode()):
                return self.git("cat-file", "blob", object_id)[:candidates.limit + 1]

            candidates.offer(path.decode(errors="replace"), int(size) if size.isdigit() else 0, regular, read)
        return candidates.choose()

    def head_commit(self):
        """HEAD's commit id and its committer time (seconds since 1970), as git reads it."""
        commit = self.head()
        text = self.git("log", "-1", "--format=%ct", commit).decode().strip()
        return commit, (int(text) if text.isdigit() else None)

    def last_change(self, commit, path, timeout):
        """The committer time of the last commit before `commit` (itself included) that changed
        `path`, a path of its tree; None, and the reason, if git could not tell (within
        `timeout` seconds: a history long enough to take longer is dated by HEAD, not refused)."""
        try:
            text = self.git("log", "-1", "--format=%ct", commit, "--", path,
                            timeout=timeout).decode().strip()
        except ValueError as error:
            return None, str(error)
        except subprocess.TimeoutExpired:
            return None, f"git took more than {timeout:.0f} s"
        return (int(text), "") if text.isdigit() else (None, f"git gave '{text[:40]}'")


def newest_time(paths):
    """The newest modification time among paths, symbolic links not followed; None if none."""
    times = []
    for path in paths:
        try:
            times.append(int(os.lstat(path).st_mtime))
        except OSError:
            pass
    return max(times) if times else None


def is_git_repository(path):
    return os.path.isdir(os.path.join(path, ".git")) or (
        os.path.isfile(os.path.join(path, "HEAD")) and os.path.isdir(os.path.join(path, "objects")))


def main():
    submission, limit, lab_files = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
    candidates = Candidates(limit, lab_files)
    # When it was submitted, as far as the submission tells: its last commit's time for a
    # repository (set by the student's machine), else its files' modification time.
    # Each lab file's own time too, for a late policy with a deadline per lab: the last commit
    # that changed it, else its modification time; an archive's own time for each of its labs.
    report = {"kind": "", "taken": {}, "problems": candidates.problems,
              "commit": "", "submitted_at": None, "time_source": "", "lab_times": {}}
    try:
        lower = submission.lower()
        if os.path.isdir(submission) and is_git_repository(submission):
            report["kind"] = "git repository (HEAD)"
            objects = GitObjects(submission)
            report["taken"] = objects.head_files(candidates)
            report["commit"], report["submitted_at"] = objects.head_commit()
            report["time_source"] = "last commit"
            # At most 20 s in all of the intake's minute, whatever the history's length.
            deadline = time.monotonic() + 20
            for name, where in report["taken"].items():
                left = deadline - time.monotonic()
                changed, why = (objects.last_change(report["commit"], where, left) if left > 0
                                else (None, "no time was left"))
                if changed is not None:
                    report["lab_times"][name] = changed
                else:
                    candidates.problems.append(f"{where}: when it last changed is not known "
                                               f"({why}): dated by the last commit")
        elif os.path.isdir(submission):
            report["kind"] = "folder"
            from_folder(submission, candidates)
            report["taken"] = candidates.choose()
            report["submitted_at"] = newest_time(os.path.join(submission, where)
                                                 for where in report["taken"].values())
            report["time_source"] = "lab files' modification time"
            for name, where in report["taken"].items():
                changed = newest_time([os.path.join(submission, where)])
                if changed is not None:
                    report["lab_times"][name] = changed
        elif lower.endswith(".zip"):
            report["kind"] = "zip"
            report["taken"] = from_zip(submission, candidates)
        elif lower.endswith((".tar.gz", ".tgz", ".tar")):
            report["kind"] = "tar"
            with open(submission, "rb") as f:
                report["taken"] = from_tar(f, candidates)
        else:
            candidates.problems.append("not a folder, .zip, .tar.gz or git repository")
        if report["kind"] in ("zip", "tar"):
            report["submitted_at"] = newest_time([submission])
            report["time_source"] = "archive's modification time"
            if report["submitted_at"] is not None:
                report["lab_times"] = {name: report["submitted_at"] for name in report["taken"]}
    except (OSError, ValueError, EOFError, zipfile.BadZipFile, tarfile.TarError,
            subprocess.TimeoutExpired, RuntimeError) as error:
        candidates.problems.append(f"the submission could not be read: {error}")
    with open("intake.json", "w") as out:
        json.dump(report, out)


main()
