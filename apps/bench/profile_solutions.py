#!/usr/bin/env python3
"""Where a sample's time goes: each reference solution rendered headless at 1 thread under
`perf record`, every profile sample attributed to Embree, a framework function, the lab, libm,
TBB, the kernel or the rest (`make profile`; README, Performance).

Usage: profile_solutions.py --build BUILD [--scene ECS] [--seconds S] [--size N] [--markdown]

Start-up (loading the scene, building Embree's BVH) and writing the image are not a sample's
time, and a flat profile cannot tell them apart from rendering: Embree's build and its traversal
are both in libembree. So each solution is profiled twice at one size, once at 1 spp and once at
N spp, and the table is their difference, the time of N - 1 spp of rendering alone, category by
category (sample counts at a fixed frequency are time). Shares are of that difference; ns/sample
is its time over its samples.

Needs `perf` (Debian: linux-perf; Ubuntu: linux-tools-generic) and permission to profile
one's own processes (kernel.perf_event_paranoid <= 2, the default).
"""
import argparse
import collections
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

FREQUENCY = 4999  # Hz: a prime, so sampling does not beat with periodic work
KIT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(KIT, "tests", "support"))
from checks import LABS  # noqa: E402

# The framework functions a sample goes through, each its own line of the table when it takes
# at least this share; the others are summed as "other framework".
OWN_LINE_SHARE = 0.01


def category(symbol, dso, lab):
    """The line of the table a profile sample's innermost function belongs to."""
    name = os.path.basename(dso)
    if "libembree" in name:
        return "Embree (traversal)"
    if name.startswith("libm.") or name.startswith("libm-"):
        return "libm: " + re.sub(r"_fma$|_avx2$|_sse2$", "", symbol)
    if "libtbb" in name:
        return "TBB"
    if dso == "[kernel.kallsyms]":
        return "kernel"
    if f"pathlab::{lab}_solution::" in symbol or f"pathlab::{lab}::" in symbol:
        return "lab: pathTrace"
    if symbol.startswith("pathlab::"):
        # pathlab::Renderer::PassTiles::render(int) -> Renderer::PassTiles::render
        short = symbol[len("pathlab::"):]
        short = short.split("(")[0]
        return "framework: " + short
    if name.startswith("libc.") or name.startswith("libstdc++") or name.startswith("ld-linux"):
        return "C/C++ runtime"
    return "other: " + (symbol if symbol != "[unknown]" else name)


def profile(viewer, scene, lab, spp, size, work):
    """Counts of profile samples per category for one headless render; and its stats."""
    data = os.path.join(work, f"{lab}-{spp}.data")
    stats = os.path.join(work, f"{lab}-{spp}.json")
    command = [viewer, "-c", scene, "--lab", lab, "--solution", "--threads", "1", "--spp",
               str(spp), "--size", str(size), str(size), "-o", os.path.join(work, "image.pfm"),
               "--stats", stats]
    subprocess.run(["perf", "record", "-q", "-F", str(FREQUENCY), "-o", data, "--", *command],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    script = subprocess.run(["perf", "script", "-i", data, "-F", "ip,sym,dso"], check=True,
                            capture_output=True, text=True).stdout
    counts = collections.Counter()
    for line in script.splitlines():
        match = re.match(r"\s*[0-9a-f]+ (.*?)\s+\((.*)\)\s*$", line)
        if match:
            counts[category(match.group(1), match.group(2), lab)] += 1
    with open(stats) as f:
        return counts, json.load(f)


def breakdown(viewer, scene, lab, seconds, size, work):
    """The render-only profile of `lab`: (share per category, ns per sample, spp)."""
    short, probe = profile(viewer, scene, lab, 1, size, work)
    rate = probe["samples_per_second"]
    spp = max(4, round(seconds * rate / (size * size)))
    long, _ = profile(viewer, scene, lab, spp, size, work)
    difference = {k: long[k] - short.get(k, 0) for k in long}
    total = sum(difference.values())
    shares = {k: v / total for k, v in difference.items()}
    ns_per_sample = total / FREQUENCY / ((spp - 1) * size * size) * 1e9
    return shares, ns_per_sample, spp


def grouped(results):
    """Each solution's shares with the small lines summed: a framework function, a libm function
    or another library gets a line of its own if it takes OWN_LINE_SHARE of some solution's
    time, the same lines for every solution."""
    largest = collections.Counter()
    for shares in results.values():
        for name, share in shares.items():
            largest[name] = max(largest[name], share)
    small_lines = {"framework: ": "framework: other functions", "other: ": "other",
                   "libm: ": "libm: other"}

    def line(name):
        for prefix, summed in small_lines.items():
            if name.startswith(prefix) and largest[name] < OWN_LINE_SHARE:
                return summed
        return name

    out = {}
    for lab, shares in results.items():
        out[lab] = collections.Counter()
        for name, share in shares.items():
            out[lab][line(name)] += share
    return out


ORDER = ("Embree", "framework", "lab", "libm", "TBB", "C/C++", "kernel", "other")


def sort_key(item):
    name, share = item
    group = next((i for i, prefix in enumerate(ORDER) if name.startswith(prefix)), len(ORDER))
    return (group, -share)


def table(shares, ns_per_sample, markdown):
    """One column per solution (`shares[lab]`: category -> share), one line per category, and
    each group's total."""
    labs = list(shares)
    names = set().union(*(set(s) for s in shares.values()))
    lines = sorted(((n, max(shares[l].get(n, 0) for l in labs)) for n in names), key=sort_key)
    rows = [["ns per sample"] + [f"{ns_per_sample[l]:.0f}" for l in labs]]
    for group in ORDER:
        members = [n for n, _ in lines if n.startswith(group)]
        if not members:
            continue
        for name in members:
            rows.append([name] + [f"{100 * shares[l].get(name, 0):.1f}%" for l in labs])
        if len(members) > 1:
            rows.append([f"{group}, all"] +
                        [f"{100 * sum(shares[l].get(n, 0) for n in members):.1f}%"
                         for l in labs])
    header = ["share of render time"] + labs
    if markdown:
        out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
        out += ["| " + " | ".join(r) + " |" for r in rows]
        return "\n".join(out)
    width = max(len(r[0]) for r in rows + [header])
    out = [header[0].ljust(width) + "".join(h.rjust(12) for h in header[1:])]
    out += [r[0].ljust(width) + "".join(c.rjust(12) for c in r[1:]) for r in rows]
    return "\n".join(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", required=True, help="the build folder, with viewer")
    parser.add_argument("--scene", default=os.path.join(KIT, "models",
                                                        "cornell_box_VI2_Specular.ecs"))
    parser.add_argument("--seconds", type=float, default=4, help="each long render (default 4)")
    parser.add_argument("--size", type=int, default=256, help="image width and height")
    parser.add_argument("--markdown", action="store_true", help="a Markdown table")
    args = parser.parse_args()
    if not shutil.which("perf"):
        sys.exit("profile: needs perf (Debian: apt-get install linux-perf; Ubuntu: "
                 "linux-tools-generic)")
    viewer = os.path.join(os.path.abspath(args.build), "viewer")
    shares, ns_per_sample = {}, {}
    with tempfile.TemporaryDirectory(prefix="pathlab-profile-") as work:
        for lab in LABS:
            shares[lab], ns_per_sample[lab], spp = breakdown(viewer, args.scene, lab,
                                                             args.seconds, args.size, work)
            print(f"profiled {lab}: {spp} spp at {args.size}x{args.size}, 1 thread",
                  file=sys.stderr, flush=True)
    print(f"{os.path.basename(args.scene)}: each solution at 1 thread, {args.size}x{args.size}; "
          f"perf at {FREQUENCY} Hz, the render alone (N spp minus 1 spp)")
    print(table(grouped(shares), ns_per_sample, args.markdown))


if __name__ == "__main__":
    main()
