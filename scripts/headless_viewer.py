"""The viewer run headless, as make convergence, make sweep and the handouts' figures run it: one
render into an image and a --stats file, the stats read back. One place for what they share: the
TODO warnings left out of what is shown (the scripts say once which steps are unwritten), the
other lines the viewer printed shown indented, and a failed render told with what it printed."""
import argparse
import contextlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time


class RenderFailed(Exception):
    """A render the viewer did not finish; its text is what the viewer printed, then why."""


class UsageError(Exception):
    """Bad input: said in one line, exit status 2, nothing written."""


KIT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def lab_estimates():
    """{lab: "depth-limited" | "unbiased"}: the labs the viewer's --lab takes, in the handouts'
    order, and the image each estimates (framework/lab_list.txt's first and third columns)."""
    labs = {}
    with open(os.path.join(KIT, "framework", "lab_list.txt"), encoding="utf-8") as f:
        for line in f:
            fields = line.split()
            if fields and not fields[0].startswith("#"):
                labs[fields[0]] = fields[2]
    return labs


def lab_routines():
    """{lab: "lobe" | None}: what each lab writes beside pathTrace (framework/lab_list.txt's
    fourth column, "lobe" for a lab that samples a glossy lobe)."""
    labs = {}
    with open(os.path.join(KIT, "framework", "lab_list.txt"), encoding="utf-8") as f:
        for line in f:
            fields = line.split()
            if fields and not fields[0].startswith("#"):
                labs[fields[0]] = fields[3] if len(fields) > 3 else None
    return labs


@contextlib.contextmanager
def output_folder(out):
    """A scratch folder beside OUT, holding an empty renders/, to write a run's files into: it
    becomes OUT (replacing what was there) only when the block ends without an exception, and
    is removed otherwise, so a failed run leaves the last good OUT as it was."""
    parent = os.path.dirname(os.path.abspath(out))
    os.makedirs(parent, exist_ok=True)
    work = tempfile.mkdtemp(prefix=f".{os.path.basename(out)}-", dir=parent)
    try:
        os.makedirs(os.path.join(work, "renders"))
        yield work
        if os.path.isdir(out):
            shutil.rmtree(out)
        os.replace(work, out)
    finally:
        if os.path.isdir(work):
            shutil.rmtree(work)


class RenderNotes:
    """The notes of a run of renders, one per render (a busy machine before a CPU figure's own),
    said once at the end: the first, and in how many more renders there were notes."""

    def __init__(self):
        self.notes = []

    def add(self, stats):
        note = stats.get("busy_note") or stats.get("cpu_note")
        if note:
            self.notes.append(note)

    def summary(self, command):
        """"make COMMAND: NOTE (and in N more render(s))", or None without notes."""
        if not self.notes:
            return None
        more = len(self.notes) - 1
        return f"make {command}: {self.notes[0]}" + (
            f" (and in {more} more render(s))" if more else "")


def command_parser(description, out_default, solution_help):
    """The options make convergence and make sweep share: --build (the folder holding viewer),
    --solution, --out (default `out_default`) and --check; each adds its own."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--build", default="build", help="the build folder holding viewer")
    parser.add_argument("--solution", action="store_true", help=solution_help)
    parser.add_argument("--out", help=f"the output folder (default {out_default})")
    parser.add_argument("--check", action="store_true", help="check the options only")
    return parser


def command_status(command, args, checked, run):
    """The exit status of `make COMMAND` (convergence, sweep), whose options `args` hold --check
    and --solution: 2 after one line when `checked()` raises UsageError or --solution is asked of
    a kit without solutions/; 0 after the check alone (--check); else `run(checked())`'s
    renders: 1 after one line when one fails (RenderFailed), nothing written, and 0."""
    try:
        options = checked()
        if args.solution and not os.path.isdir(os.path.join(KIT, "solutions")):
            raise UsageError("--solution: this kit has no reference solutions (solutions/)")
    except UsageError as e:
        print(f"make {command}: {e}", file=sys.stderr)
        return 2
    if args.check:
        return 0
    try:
        run(options)
    except RenderFailed as e:
        print(f"{e}; nothing written", file=sys.stderr)
        return 1
    return 0


# The viewer's warning for a PATHLAB_TODO step, once per step: "FILE:LINE: TODO(STEP) is not done
# yet ..." (pathlab/todo.h's TodoNotDoneWords).
TODO_WARNING = "is not done yet"


def render(viewer, options, image, stats, failure):
    """Runs `viewer OPTIONS -o IMAGE --stats STATS`; returns the stats as a dict with
    "wall_seconds" (the whole run's, start-up included) added. On a non-zero exit raises
    RenderFailed with the viewer's lines and then `failure` with the exit status."""
    start = time.monotonic()
    run = subprocess.run([viewer, *options, "-o", image, "--stats", stats],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                         errors="replace")
    problems = [line for line in run.stderr.splitlines() if TODO_WARNING not in line]
    if run.returncode != 0:
        raise RenderFailed("\n".join(problems + [f"{failure} (viewer exit status "
                                                 f"{run.returncode})"]))
    for line in problems:
        print(f"  {line}", file=sys.stderr)
    with open(stats) as f:
        result = json.load(f)
    result["wall_seconds"] = time.monotonic() - start
    return result
