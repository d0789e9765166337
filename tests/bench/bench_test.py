#!/usr/bin/env python3
"""Tests of the benchmark (apps/bench), ctest label `bench`. They check what it measures, never
how fast anything is.

  bench_test.py smoke BENCH      bench runs at a tiny size; its JSON parses with every field,
                                 the figures per CPU-second beside those per second of wall time
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

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import LABS  # noqa: E402

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


def share(value, per_thread, what):
    """A share of the cores the timed threads had: above 0 (0 would mean the CPU time was not
    measured), and with per-thread clocks at most 1 but for the clocks' rounding. The process's
    clock (the fallback) counts every thread of the process, TBB's idle ones too, which over a
    tiny pass can be more than the pass's own threads."""
    limit = 1.05 if per_thread else math.inf
    if not (isinstance(value, (int, float)) and math.isfinite(value) and 0 < value <= limit):
        sys.exit(f"{what} should be a share of the cores in (0, {limit}], is {value!r}")


def efficiency(value, what):
    """The share of a render's time that is Embree's traversal: above 0, and not far above 1 (a
    render cannot trace its rays faster than Embree alone, but for the spread of two timings)."""
    if not (isinstance(value, (int, float)) and math.isfinite(value) and 0 < value <= 1.5):
        sys.exit(f"{what} should be in (0, 1.5], is {value!r}")


def note(value, what):
    if not isinstance(value, str):
        sys.exit(f"{what} should be text (empty when the machine was not busy), is {value!r}")


def rgb(value, what):
    if not (isinstance(value, list) and len(value) == 3 and
            all(isinstance(c, (int, float)) and math.isfinite(c) for c in value)):
        sys.exit(f"{what} should be three numbers, is {value!r}")
    return value


def smoke(bench):
    with tempfile.TemporaryDirectory() as folder:
        report, table = run_bench(bench, [
            "--size", "24", "16", "--spp", "1", "--passes", "1", "--threads", "2",
            # Frames of 512 spp take Embree tens of milliseconds of CPU time, well above its
            # start-up's 5 ms: enough to difference (embree_pathtracer.cpp).
            "--peer-spp", "512", "--peer-image-spp", "2",
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
                positive(scene["raw"][threads][f"{kind}_per_cpu_second"],
                         f"{name} raw {threads} {kind} rays per CPU-second")
        note(scene["busy_note"], f"{name} busy note")
        labs = [s["lab"] for s in scene["solutions"]]
        if labs != list(LABS):
            sys.exit(f"{name}: solutions {labs}")
        for s in scene["solutions"]:
            what = f"{name} {s['lab']}"
            for threads in ("one_thread", "threads"):
                figures = s[threads]
                positive(figures["samples_per_second"], f"{what} {threads} samples/s")
                positive(figures["rays_per_second"]["intersect"], f"{what} {threads} intersect/s")
                positive(figures["raw_mix_rays_per_second"], f"{what} {threads} raw mix rays/s")
                positive(figures["samples_per_cpu_second"], f"{what} {threads} samples/CPU-s")
                for kind in ("intersect", "occluded", "total"):
                    positive(figures["rays_per_cpu_second"][kind],
                             f"{what} {threads} {kind} rays/CPU-s")
                positive(figures["raw_mix_rays_per_cpu_second"],
                         f"{what} {threads} raw mix rays/CPU-s")
                share(figures["cpu_share"], report["cpu_clock"] == "per-thread",
                      f"{what} {threads} CPU share")
                efficiency(figures["efficiency"], f"{what} {threads} efficiency (CPU time)")
                positive(figures["efficiency_wall"], f"{what} {threads} efficiency (wall clock)")
                check_cpu_figures(figures, 1 if threads == "one_thread" else scene["threads"],
                                  f"{what} {threads}")
            positive(s["scaling"], f"{what} scaling")
            if s["efficiency"] != s["threads"]["efficiency"]:
                sys.exit(f"{what}: the headline efficiency is not the all-threads one")
            if s["efficiency_wall"] != s["threads"]["efficiency_wall"]:
                sys.exit(f"{what}: the headline wall-clock efficiency is not the all-threads one")

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
    if (len(scaling) != 1 or
            "\nScaling (wall clock: how soon a pass is done): roulette solution" not in table):
        sys.exit(f"no scaling figures: {scaling}\n{table}")
    threads = [p["threads"] for p in scaling[0]["by_threads"]]
    if threads[:4] != [1, 2, 4, 8]:
        sys.exit(f"scaling measured at threads {threads}, not 1, 2, 4, 8 (more than this "
                 "machine's cores included)")
    if [p["tile_size"] for p in scaling[0]["by_tile_size"]] != [8, 16, 32, 64]:
        sys.exit(f"tile sizes measured: {scaling[0]['by_tile_size']}")
    for p in scaling[0]["by_threads"] + scaling[0]["by_tile_size"]:
        positive(p["samples_per_second"], f"scaling samples/s at {p}")
    note(scaling[0]["busy_note"], "the scaling's busy note")
    positive(scaling[0]["hand_off_ms"], "the window's hand-off between frames")
    if not 0 < scaling[0]["hand_off_share"] <= scaling[0]["hand_off_share_at_64_threads"] < 1:
        sys.exit(f"the hand-off's share should grow with threads: {scaling[0]}")

    if report["cpu_clock"] != "per-thread" and not report["cpu_clock"].startswith("process"):
        sys.exit(f"cpu_clock: {report['cpu_clock']!r}")
    for heading in ("per CPU-second", "wall clock", "Scaling (wall clock"):
        if heading not in table:
            sys.exit(f"no table says '{heading}':\n{table}")

    memory = report["memory"]
    if not memory["measured"]:
        sys.exit(f"peak memory not measured: {memory.get('note')}")
    positive(memory["peak_mib"], "peak memory")
    keeps_earlier_json_on_failure(bench)
    print(f"bench ran; {len(scenes)} scene(s); JSON complete; a failed run keeps the earlier JSON")


def check_cpu_figures(figures, threads, what):
    """A pass's figures per CPU-second and per second are of the same samples and rays: their
    ratios are all the one share of the cores the threads had, and the efficiency by CPU time
    is the render's rays per CPU-second over Embree's alone."""
    cores = min(threads, len(os.sched_getaffinity(0)))
    cpu_seconds_per_second = figures["samples_per_second"] / figures["samples_per_cpu_second"]
    for kind in ("intersect", "occluded", "total"):
        ratio = figures["rays_per_second"][kind] / figures["rays_per_cpu_second"][kind]
        if not math.isclose(ratio, cpu_seconds_per_second, rel_tol=1e-9):
            sys.exit(f"{what}: {kind} rays and samples are not of one pass: {figures}")
    if not math.isclose(cpu_seconds_per_second / cores, figures["cpu_share"], rel_tol=1e-9):
        sys.exit(f"{what}: the CPU share is not CPU time over wall time x cores: {figures}")
    expected = figures["rays_per_cpu_second"]["total"] / figures["raw_mix_rays_per_cpu_second"]
    if not math.isclose(figures["efficiency"], expected, rel_tol=1e-9):
        sys.exit(f"{what}: the efficiency is not by CPU time: {figures}")
    expected = figures["rays_per_second"]["total"] / figures["raw_mix_rays_per_second"]
    if not math.isclose(figures["efficiency_wall"], expected, rel_tol=1e-9):
        sys.exit(f"{what}: efficiency_wall is not by wall-clock time: {figures}")


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
        if peer["cpu_note"]:
            sys.exit(f"no CPU-time comparison at path length {peer['max_path_length']}: "
                     f"{peer['cpu_note']}")
        positive(peer["embree_samples_per_cpu_second"], "Embree pathtracer samples per CPU-second")
        positive(peer["ours_samples_per_cpu_second"], "PathLab samples per CPU-second")
        positive(peer["cpu_ratio"], "PathLab / Embree by CPU time")
        if not math.isclose(peer["cpu_ratio"], peer["ours_samples_per_cpu_second"] /
                            peer["embree_samples_per_cpu_second"], rel_tol=1e-9):
            sys.exit(f"cpu_ratio is not PathLab's samples per CPU-second over Embree's: {peer}")
        rounds = peer["embree_cpu_seconds_per_frame"]
        if len(rounds) != peer["rounds"]:
            sys.exit(f"Embree's CPU time per frame of {len(rounds)} rounds, not {peer['rounds']}")
        for seconds in rounds:
            positive(seconds, "Embree's CPU time per frame (two runs differenced)")
        # Of the best round whose frames took enough CPU time beside the start-up's to be
        # differenced: not always the round of least CPU time per frame.
        samples = peer["width"] * peer["height"] * peer["spp"]
        if not any(math.isclose(peer["embree_samples_per_cpu_second"], samples / seconds,
                                rel_tol=1e-9) for seconds in rounds):
            sys.exit(f"Embree's samples per CPU-second are not of one of its rounds: {peer}")
        positive(peer["embree_start_cpu_seconds"], "Embree's start-up CPU time")
        # Whole processes' CPU time over frames' wall time: work between frames can take the
        # share above 1, so only its presence is checked.
        positive(peer["embree_cpu_share"], "Embree's pathtracer's CPU share")
        positive(peer["ours_cpu_share"], "PathLab's CPU share beside Embree's pathtracer")
        note(peer["busy_note"], "the comparison's busy note")
        if "samples per CPU-second" not in table:
            sys.exit(f"the comparison with Embree's pathtracer is not by CPU time:\n{table}")
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
