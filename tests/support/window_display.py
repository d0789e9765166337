"""A display for the tests of the viewer's window: a virtual X server (Xvfb), started as the
handouts' figures and the bench start one (scripts/virtual_display.py), and stopped however the
test's block ends, so that no server outlives a failed check."""
import contextlib
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from virtual_display import start_xvfb  # noqa: E402


@contextlib.contextmanager
def virtual_display_env(screen="800x600x24"):
    """Starts Xvfb with a screen of `screen` (WIDTHxHEIGHTxDEPTH) for the block, and yields this
    process's environment with DISPLAY naming it: the environment to open the windows in."""
    server, display = start_xvfb(screen)
    try:
        yield dict(os.environ, DISPLAY=display)
    finally:
        server.terminate()
        server.wait()
