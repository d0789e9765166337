#!/usr/bin/env python3
"""Tests of the benchmark (apps/bench), ctest label `bench`. They check what it measures, never
how fast anything is.

  bench_test.py smoke BENCH      bench runs at a tiny size; its JSON parses with every field
  bench_test.py agreement BENCH  PathLab's importance solution and Embree's own pathtracer give
                                 Embree's Cornell box the same mean radiance, at each path length
                                 the bench compares (2, 4 and 8); skipped (exit 77) when Embree's
                                 pathtracer (Debian package embree-tools) is absent
"""

import json
import math
import os
import signal
import subprocess
import sys
import tempfile

SKIPPED = 77  # ctest's SKIP_RETURN_CODE for these tests

# Per channel and path length, the two means may differ by at most this many standard errors of
# their difference. Both renders are deterministic (fixed seeds), so the verdict never changes
# from run to run; for a correct pair of estimators one comparison fails with probability 6.3e-5,
# and the 9 of the test (3 channels, 3 path lengths) with probability below 6e-4.
TOLERANCE_SE = 4.0
PATH_LENGTHS = [2, 4, 8]


def run_bench(bench, arguments, folder):
    out = os.path.join(folder, "bench.json")
    result = subprocess.run([bench, *arguments, "--json", out], capture_output=True, text=True,
                            timeout=300)
    if result.returncode != 0:
        sys.exit(f"bench failed ({result.returncode}):\n{result.stdout}\n{result.stderr}")
    with open(out) as f:
        return json.load(f), result.stdout


def positive(value, what):
    if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
        sys.exit(f"{what} should be a positive number, is {value!r}")


def rgb(value, what):
    if not (isinstance(value, list) and len(value) == 3 and
            all(isinstance(c, (int, float)) and math.isfinite(c) for c in value)):
        sys.exit(f"{what} should be three numbers, is {value!r}")
    return value


def smoke(bench):
    with tempfile.TemporaryDirectory() as folder:
        report, table = run_bench(bench, [
            "--size", "24", "16", "--spp", "1", "--passes", "1", "--threads", "2",
            "--peer-spp", "1", "--peer-image-spp", "2",
            "--memory-size", "32", "32", "--memory-frames", "2", "--first-frame-runs", "1"],
            folder)

    scenes = report["scenes"]
    if not scenes:
        sys.exit("no scene was measured")
    for scene in scenes:
        name = scene["scene"]
        if f"\n{name}: " not in table:
            sys.exit(f"the table has no section for {name}:\n{table}")
        positive(scene["triangles"], f"{name} triangles")
        if (scene["width"], scene["height"], scene["threads"]) != (24, 16, 2):
            sys.exit(f"{name}: size or threads not as asked: {scene}")
        for threads in ("one_thread", "threads"):
            for kind in ("camera", "closest_hit", "occlusion"):
                positive(scene["raw"][threads][kind], f"{name} raw {threads} {kind} rays/s")
        labs = [s["lab"] for s in scene["solutions"]]
        if labs != ["branching", "uniform", "importance", "roulette"]:
            sys.exit(f"{name}: solutions {labs}")
        for s in scene["solutions"]:
            what = f"{name} {s['lab']}"
            for threads in ("one_thread", "threads"):
                figures = s[threads]
                positive(figures["samples_per_second"], f"{what} {threads} samples/s")
                positive(figures["rays_per_second"]["intersect"], f"{what} {threads} intersect/s")
                positive(figures["raw_mix_rays_per_second"], f"{what} {threads} raw mix rays/s")
                positive(figures["efficiency"], f"{what} {threads} efficiency")
            positive(s["scaling"], f"{what} scaling")
            if s["efficiency"] != s["threads"]["efficiency"]:
                sys.exit(f"{what}: the headline efficiency is not the all-threads one")

    peers = report["embree_pathtracer"]
    if [p["max_path_length"] for p in peers] != PATH_LENGTHS:
        sys.exit(f"path lengths compared: {[p['max_path_length'] for p in peers]}")
    for peer in peers:
        check_peer(peer, table)

    first = report["first_frame"]
    if first["measured"]:
        positive(first["first_frame_ms"], "start to first frame")
        positive(first["first_image_ms"], "start to first image on screen")
        if first["first_image_ms"] < first["first_frame_ms"]:
            sys.exit(f"the first image was on screen before the first frame arrived: {first}")
        if "start to first image on screen" not in table:
            sys.exit(f"the table has no first-frame latency:\n{table}")
    elif not first["note"]:
        sys.exit("the first-frame latency was not measured and says not why")

    scaling = report["scaling"]
    if len(scaling) != 1 or "\nScaling: roulette solution" not in table:
        sys.exit(f"no scaling figures: {scaling}\n{table}")
    threads = [p["threads"] for p in scaling[0]["by_threads"]]
    if threads[:4] != [1, 2, 4, 8]:
        sys.exit(f"scaling measured at threads {threads}, not 1, 2, 4, 8 (more than this "
                 "machine's cores included)")
    if [p["tile_size"] for p in scaling[0]["by_tile_size"]] != [8, 16, 32, 64]:
        sys.exit(f"tile sizes measured: {scaling[0]['by_tile_size']}")
    for p in scaling[0]["by_threads"] + scaling[0]["by_tile_size"]:
        positive(p["samples_per_second"], f"scaling samples/s at {p}")
    positive(scaling[0]["hand_off_ms"], "the window's hand-off between frames")
    if not 0 < scaling[0]["hand_off_share"] <= scaling[0]["hand_off_share_at_64_threads"] < 1:
        sys.exit(f"the hand-off's share should grow with threads: {scaling[0]}")

    memory = report["memory"]
    if not memory["measured"]:
        sys.exit(f"peak memory not measured: {memory.get('note')}")
    positive(memory["peak_mib"], "peak memory")
    keeps_earlier_json_on_failure(bench)
    print(f"bench ran; {len(scenes)} scene(s); JSON complete; a failed run keeps the earlier JSON")


def keeps_earlier_json_on_failure(bench):
    """A run that stops before its end, by bad input or interrupted while it measures, leaves the
    JSON of an earlier run as it was, and no temporary file."""
    with tempfile.TemporaryDirectory() as folder:
        out = os.path.join(folder, "bench.json")
        earlier = '{"scenes": []}\n'
        with open(out, "w") as f:
            f.write(earlier)

        def unchanged(after):
            with open(out) as f:
                if f.read() != earlier:
                    sys.exit(f"bench {after} replaced the JSON of an earlier run")
            if os.listdir(folder) != ["bench.json"]:
                sys.exit(f"bench {after} left files behind: {os.listdir(folder)}")

        missing = os.path.join(folder, "missing.ecs")
        result = subprocess.run([bench, "--scene", missing, "--json", out], capture_output=True,
                                text=True, timeout=60)
        if result.returncode != 2 or "missing.ecs" not in result.stderr:
            sys.exit(f"bench on a missing scene: exit {result.returncode}, {result.stderr!r}")
        unchanged("on a missing scene")

        running = subprocess.Popen([bench, "--json", out], stdout=subprocess.DEVNULL,
                                   stderr=subprocess.PIPE, text=True)
        line = running.stderr.readline()  # "bench: measuring ...": past the start, into the work
        running.send_signal(signal.SIGINT)
        running.communicate(timeout=60)
        if not line.startswith("bench: measuring"):
            sys.exit(f"bench began with {line!r}, not with a scene")
        unchanged("interrupted while it measured")


def check_peer(peer, table):
    if peer["measured"]:
        positive(peer["embree_samples_per_second"], "Embree pathtracer samples/s")
        positive(peer["ours_samples_per_second"], "PathLab samples/s on Embree's box")
        positive(peer["ratio"], "PathLab / Embree")
        if peer["max_path_length"] != peer["max_depth"] + 1:
            sys.exit(f"path length {peer['max_path_length']} != max-depth {peer['max_depth']} + 1")
        rgb(peer["mean_radiance"]["embree"], "Embree's mean radiance")
        rgb(peer["mean_radiance"]["ours"], "PathLab's mean radiance")
        if "Embree's pathtracer on" not in table:
            sys.exit(f"the table has no comparison with Embree's pathtracer:\n{table}")
    elif not peer["note"]:
        sys.exit("the comparison with Embree's pathtracer was not measured and says not why")


def agreement(bench):
    with tempfile.TemporaryDirectory() as folder:
        report, table = run_bench(bench, [
            "--peer-only", "--size", "128", "128", "--passes", "1", "--peer-spp", "1",
            "--peer-image-spp", "64"], folder)
    print(table)
    failures = []
    for peer in report["embree_pathtracer"]:
        if not peer["measured"]:
            print(f"skipped: {peer['note']}")
            sys.exit(SKIPPED)
        length = peer["max_path_length"]
        embree = rgb(peer["mean_radiance"]["embree"], "Embree's mean radiance")
        ours = rgb(peer["mean_radiance"]["ours"], "PathLab's mean radiance")
        error = rgb(peer["standard_error"], "standard error")
        if peer["ours_max_pixel"] >= 1:
            sys.exit(f"PathLab's brightest pixel is {peer['ours_max_pixel']} at path length "
                     f"{length}: Embree's 8-bit image clips there, so the means cannot agree; "
                     "dim --peer-light-scale")
        for channel, e, o, se in zip("rgb", embree, ours, error):
            positive(e, f"Embree's mean ({channel}, path length {length})")
            positive(se, f"standard error ({channel}, path length {length})")
            z = (o - e) / se
            print(f"path length {length}, {channel}: Embree {e:.5f}  PathLab {o:.5f}  "
                  f"difference {z:+.2f} standard errors")
            if abs(z) > TOLERANCE_SE:
                failures.append(f"{channel} at path length {length}")
    if failures:
        sys.exit(f"the mean radiances differ by more than {TOLERANCE_SE} standard errors: "
                 f"{', '.join(failures)}")
    print("the mean radiances agree at every path length")


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] not in ("smoke", "agreement"):
        sys.exit(__doc__)
    {"smoke": smoke, "agreement": agreement}[sys.argv[1]](sys.argv[2])
