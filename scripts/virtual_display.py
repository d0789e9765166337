"""A virtual X server (Xvfb) for the viewer's window where no display exists: the window's tests,
the handouts' figures and the bench's first-frame latency all start one this way."""
import os
import subprocess


def start_xvfb(screen="1024x768x24"):
    """Starts Xvfb on a free display number, which it reports on a pipe (-displayfd), so two
    runs on one machine never race for a number. Returns (server process, ":N")."""
    read, write = os.pipe()
    server = subprocess.Popen(["Xvfb", "-displayfd", str(write), "-screen", "0", screen,
                               "-nolisten", "tcp"], pass_fds=[write], stderr=subprocess.DEVNULL)
    os.close(write)
    number = b""
    try:
        while not number.endswith(b"\n"):
            chunk = os.read(read, 16)
            if not chunk:
                raise RuntimeError("Xvfb did not start (is the xvfb package installed?)")
            number += chunk
    finally:
        os.close(read)
    return server, ":" + number.decode().strip()
