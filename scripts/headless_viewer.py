"""The viewer run headless, as make convergence, make sweep and the handouts' figures run it: one
render into an image and a --stats file, the stats read back. One place for what they share: the
TODO warnings left out of what is shown (the scripts say once which steps are unwritten), the
other lines the viewer printed shown indented, and a failed render told with what it printed."""
import json
import subprocess
import sys
import time


class RenderFailed(Exception):
    """A render the viewer did not finish; its text is what the viewer printed, then why."""


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
