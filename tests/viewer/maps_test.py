#!/usr/bin/env python3
"""The viewer's error against a reference and its noise and efficiency maps, from the outside.

Usage: maps_test.py VIEWER MODELS_DIR. Each check prints PASS/FAIL; the script exits non-zero if
any failed. Fixed seeds throughout.

- viewer -o ... --reference REF prints relMSE (epsilon 0.01) and the relative RMSE, and --stats
  writes them under "reference" beside the fields it always had: 0 for a render against itself;
  against a half-bright copy of itself (made here, as .pfm), mean over pixels and channels of
  (r/2)^2 / ((r/2)^2 + 0.01), computed here from the render's own pixels.
- Bad input (a reference of another size, a missing or unreadable one, --error-image without
  --reference, a map that is neither .exr nor .png, --noise-image at 1 spp, an unknown --view)
  is one line naming the option, exit status 2, and nothing written; so is --efficiency-image at
  1 spp and a --map-range that is no log scale or has no map to draw.
- The efficiency map is 1/(relative standard error^2 x CPU-seconds) of the same run's noise map;
  --map-range LO HI colours two renders' PNGs on that one scale.
- The noise map's PNG, read here pixel by pixel: beneath the image a scale bar that runs through
  the palette (black, blue, green, yellow, red) from left to right, with its end values written
  under it; the printed scale is whole decades around the values of the map's EXR (written in
  the same run), and every pixel's colour is the palette's at its EXR value's place on that log
  scale, the palette evaluated here from its definition (pathlab/images/false_colour.h).
- The window's noise and efficiency views (--view) under a virtual X server (Xvfb), captured
  with --capture-window: the image is on the palette (or grey where there is no value), and the
  panel shows the scale bar.
"""
import json
import math
import os
import re
import struct
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))
from checks import check, exit_code  # noqa: E402
from png_pixels import read_png  # noqa: E402
from window_display import virtual_display_env  # noqa: E402

VIEWER, MODELS = sys.argv[1], sys.argv[2]
SCENE = os.path.join(MODELS, "cornell_box_VI2_Specular.ecs")
WIDTH, HEIGHT = 48, 36
COMMON = ["-c", SCENE, "--size", str(WIDTH), str(HEIGHT), "--lab", "importance", "--solution",
          "--seed", "5"]
EPSILON = 0.01
PALETTE = [(0, 0, 0), (0, 0, 1), (0, 1, 0), (1, 1, 0), (1, 0, 0)]
REFERENCE_LINE = re.compile(r"^  against (.+): relMSE ([-\d.e+]+) \(epsilon ([\d.e+-]+)\), "
                            r"relative RMSE ([-\d.e+]+)$", re.M)


def viewer(*arguments, env=None):
    return subprocess.run([VIEWER, *arguments], capture_output=True, text=True, timeout=300,
                          env=env)


def read_pfm(path):
    """(width, height, [floats], top row first) of a colour .pfm."""
    data = open(path, "rb").read()
    header, rest = data.split(b"\n", 3)[:3], data.split(b"\n", 3)[3]
    width, height = map(int, header[1].split())
    little = float(header[2]) < 0
    values = struct.unpack(("<" if little else ">") + f"{3 * width * height}f",
                           rest[:12 * width * height])
    rows = [values[3 * width * y:3 * width * (y + 1)] for y in range(height)]
    return width, height, [v for row in reversed(rows) for v in row]  # PFM is bottom-up


def write_pfm(path, width, height, values):
    rows = [values[3 * width * y:3 * width * (y + 1)] for y in range(height)]
    with open(path, "wb") as out:
        out.write(f"PF\n{width} {height}\n-1\n".encode())
        for row in reversed(rows):
            out.write(struct.pack(f"<{len(row)}f", *row))


def exr_values(path):
    """The first channel of every pixel of an EXR, row-major, by oiiotool --dumpdata."""
    out = subprocess.run(["oiiotool", "--dumpdata", path], capture_output=True, text=True,
                         check=True).stdout
    pixels = {}
    for m in re.finditer(r"Pixel \((\d+), (\d+)\): ([-\d.e+naif]+)", out):
        pixels[(int(m.group(1)), int(m.group(2)))] = float(m.group(3))
    return [pixels[(x, y)] for y in range(HEIGHT) for x in range(WIDTH)]


def heat(t):
    """The palette at t in [0, 1], as 8-bit RGB, as false_colour.cpp defines it."""
    t = min(max(t, 0.0), 1.0) * 4
    i = min(int(t), 3)
    f = t - i
    return tuple(int(255 * (PALETTE[i][c] * (1 - f) + PALETTE[i + 1][c] * f)) for c in range(3))


def palette_place(rgb):
    """Where a colour sits on the palette (0..1), or None for one that is not on it."""
    best, place = 1e9, None
    for k in range(401):
        d = max(abs(a - b) for a, b in zip(heat(k / 400), rgb))
        if d < best:
            best, place = d, k / 400
    return place if best <= 3 else None


def reference_figures(tmp):
    ref = os.path.join(tmp, "ref.pfm")
    run = viewer(*COMMON, "--spp", "16", "-o", ref)
    check(run.returncode == 0, f"the reference renders ({run.stderr.strip()})")
    stats = os.path.join(tmp, "same.json")
    run = viewer(*COMMON, "--spp", "16", "-o", os.path.join(tmp, "same.pfm"), "--reference", ref,
                 "--stats", stats)
    m = REFERENCE_LINE.search(run.stdout)
    check(run.returncode == 0 and m is not None and float(m.group(2)) == 0 and
          float(m.group(4)) == 0 and float(m.group(3)) == EPSILON,
          f"against itself relMSE and relative RMSE are 0, epsilon 0.01: {m and m.group(0)!r}")
    s = json.load(open(stats)) if os.path.exists(stats) else {}
    check(s.get("reference", {}).get("rel_mse") == 0 and s["reference"]["relative_rmse"] == 0 and
          s["reference"]["file"] == ref and s["reference"]["rel_mse_epsilon"] == EPSILON and
          all(k in s for k in ("noise", "efficiency", "mean_radiance", "spp", "seconds")),
          f"--stats adds \"reference\" beside its fields: {s.get('reference')}")

    width, height, image = read_pfm(ref)
    half = os.path.join(tmp, "half.pfm")
    write_pfm(half, width, height, [v / 2 for v in image])
    # The render is r, its reference r/2: (r - r/2)^2 / ((r/2)^2 + eps) = (r/2)^2 / ((r/2)^2 + eps).
    expected_mse = sum((r / 2) ** 2 / ((r / 2) ** 2 + EPSILON) for r in image) / len(image)
    expected_rmse = (math.sqrt(sum((r / 2) ** 2 for r in image) / len(image)) /
                     (sum(r / 2 for r in image) / len(image)))
    run = viewer(*COMMON, "--spp", "16", "-o", os.path.join(tmp, "again.pfm"), "--reference", half)
    m = REFERENCE_LINE.search(run.stdout)
    check(m is not None and abs(float(m.group(2)) - expected_mse) < 1e-4 * expected_mse and
          abs(float(m.group(4)) - expected_rmse) < 1e-4 * expected_rmse,
          f"against a half-bright copy relMSE {m and m.group(2)} (by hand {expected_mse:.6g}), "
          f"relative RMSE {m and m.group(4)} (by hand {expected_rmse:.6g})")
    return ref


def bad_input_writes_nothing(tmp, ref):
    other = os.path.join(tmp, "other.pfm")
    viewer("-c", SCENE, "--size", "20", "20", "--spp", "1", "--solution", "-o", other)
    text = os.path.join(tmp, "text.exr")
    open(text, "w").write("not an image\n")
    cases = [
        (["--reference", other], "--reference"),
        (["--reference", os.path.join(tmp, "missing.exr")], "--reference"),
        (["--reference", text], "--reference"),
        (["--error-image", "E.png"], "--error-image"),
        (["--reference", ref, "--error-image", "E.pfm"], "--error-image"),
        (["--noise-image", "N.hdr"], "--noise-image"),
        (["--noise-image", "N.png", "--spp", "1"], "--noise-image"),
        (["--efficiency-image", "E.png", "--spp", "1"], "--efficiency-image"),
        (["--noise-image", "N.png", "--map-range", "0", "1"], "--map-range"),
        (["--noise-image", "N.png", "--map-range", "1", "0.1"], "--map-range"),
        (["--map-range", "0.01", "1"], "--map-range"),
        (["--view", "sideways"], "--view"),
    ]
    for extra, option in cases:
        out = tempfile.mkdtemp(dir=tmp)
        named = [os.path.join(out, a) if a[:1] in "EN" and "." in a else a for a in extra]
        run = viewer(*COMMON, "--spp", "4", "-o", os.path.join(out, "out.exr"), "--stats",
                     os.path.join(out, "stats.json"), *named)
        lines = run.stderr.strip().splitlines()
        check(run.returncode == 2 and len(lines) == 1 and option in lines[0] and
              not os.listdir(out),
              f"{' '.join(extra)}: exit {run.returncode}, one line naming {option}, nothing "
              f"written ({os.listdir(out)}): {run.stderr.strip()!r}")


def noise_png_has_its_scale(tmp):
    exr, png = os.path.join(tmp, "noise.exr"), os.path.join(tmp, "noise.png")
    run = viewer(*COMMON, "--spp", "32", "-o", os.path.join(tmp, "n.exr"), "--noise-image", exr,
                 "--noise-image", png)
    m = re.search(r"wrote .*noise\.png: .*log scale ([\de.+-]+) \(black\) to ([\de.+-]+) \(red\)",
                  run.stdout)
    check(run.returncode == 0 and m is not None and os.path.exists(exr),
          f"--noise-image writes both files and prints the PNG's scale: {run.stdout.strip()!r}")
    if not m:
        return
    low, high = float(m.group(1)), float(m.group(2))
    values = exr_values(exr)
    positive = sorted(v for v in values if v > 0)
    decades = math.log10(high / low)
    check(abs(math.log10(low) - round(math.log10(low))) < 1e-6 and decades >= 1 - 1e-6 and
          low <= positive[len(positive) * 2 // 100] and high >= positive[len(positive) * 98 // 100],
          f"the scale {low:g} .. {high:g} is whole decades around the values "
          f"({positive[0]:.3g} .. {positive[-1]:.3g})")
    width, height, rows = read_png(png)
    check(width == WIDTH and height > HEIGHT + 8, f"the PNG is the map with a strip beneath "
                                                  f"({width}x{height})")
    off = pixels_off_scale(values, rows, low, high)
    check(off == 0, f"every pixel has the palette's colour at its value's place on the scale "
                    f"({off} of {WIDTH * HEIGHT} differ)")
    bar = None
    for y in range(HEIGHT, height):
        places = [palette_place(rgb) for rgb in rows[y]]
        if all(p is not None for p in places) and places[0] < 0.05 and places[-1] > 0.95 and \
                all(b >= a for a, b in zip(places, places[1:])):
            bar = y
            break
    check(bar is not None, "beneath the map, a bar runs through the palette from black on the "
                           "left to red on the right")
    if bar is None:
        return
    label_rows = rows[bar + 1:]
    white = [(x, y) for y, row in enumerate(label_rows) for x, rgb in enumerate(row)
             if rgb == (255, 255, 255)]
    check(any(x < WIDTH // 3 for x, _ in white) and any(x > 2 * WIDTH // 3 for x, _ in white),
          f"the bar's two ends are labelled beneath it ({len(white)} label pixels)")


def pixels_off_scale(values, rows, low, high):
    """How many pixels of a map's PNG are not the palette's colour at their EXR value's place on
    the log scale low..high (grey for no value)."""
    decades = math.log10(high / low)
    off = 0
    for y in range(HEIGHT):
        for x in range(WIDTH):
            v = values[y * WIDTH + x]
            want = (128, 128, 128) if v <= 0 else heat(math.log10(v / low) / decades)
            off += max(abs(a - b) for a, b in zip(want, rows[y][x])) > 2
    return off


def efficiency_map_and_fixed_range(tmp):
    """--efficiency-image is 1/(relative standard error^2 x CPU-seconds) of the noise map of the
    same run, computed here from the two EXRs and --stats' cpu_seconds; --map-range puts two
    renders' PNGs on the one scale it names."""
    noise, efficiency = os.path.join(tmp, "n2.exr"), os.path.join(tmp, "e2.exr")
    stats = os.path.join(tmp, "e2.json")
    run = viewer(*COMMON, "--spp", "16", "-o", os.path.join(tmp, "e2.pfm"), "--noise-image", noise,
                 "--efficiency-image", efficiency, "--stats", stats)
    check(run.returncode == 0 and os.path.exists(efficiency) and "CPU-seconds per sample" in run.stdout,
          f"--efficiency-image writes the map, charged by CPU time: {run.stdout.strip()[-200:]!r}")
    if run.returncode != 0:
        return
    cpu = json.load(open(stats))["cpu_seconds"]
    pairs = list(zip(exr_values(noise), exr_values(efficiency)))
    wrong = [(n, e) for n, e in pairs
             if (n > 0 and abs(e - 1 / (n * n * cpu)) > 1e-3 * e) or (n <= 0 and e != 0)]
    check(cpu > 0 and not wrong and any(n > 0 for n, _ in pairs),
          f"each pixel's efficiency is 1/(noise^2 x {cpu:.3g} CPU-s) ({len(wrong)} of "
          f"{len(pairs)} differ: {wrong[:3]})")
    for spp in ("4", "64"):
        exr, png = os.path.join(tmp, f"r{spp}.exr"), os.path.join(tmp, f"r{spp}.png")
        run = viewer(*COMMON, "--spp", spp, "-o", os.path.join(tmp, f"r{spp}.pfm"),
                     "--noise-image", exr, "--noise-image", png, "--map-range", "0.001", "1")
        check(run.returncode == 0 and "log scale 0.001 (black) to 1 (red) as --map-range set"
              in run.stdout, f"--map-range 0.001 1 at {spp} spp: the PNG's scale is the one given "
                             f"({run.stdout.strip()[-160:]!r})")
        if run.returncode != 0:
            continue
        _, _, rows = read_png(png)
        off = pixels_off_scale(exr_values(exr), rows, 0.001, 1)
        check(off == 0, f"... and at {spp} spp every pixel is coloured on it ({off} differ)")


def window_maps(tmp):
    with virtual_display_env() as env:
        for view in ("noise", "efficiency"):
            shot = os.path.join(tmp, f"window-{view}.png")
            run = viewer(*COMMON[:2], "--size", "640", "480", "--lab", "importance", "--solution",
                         "--seed", "5", "--view", view, "--frames", "8", "--capture-window", shot,
                         env=env)
            check(run.returncode == 0 and os.path.exists(shot),
                  f"--view {view} --frames 8 --capture-window: exit {run.returncode} "
                  f"({run.stderr.strip()})")
            if not os.path.exists(shot):
                continue
            width, height, rows = read_png(shot)
            # Below the panel (which keeps to the top left), the image is the map.
            below = [rgb for row in rows[height * 3 // 4:] for rgb in row]
            on_palette = sum(1 for rgb in below if rgb == (128, 128, 128) or min(rgb) <= 3)
            check(on_palette >= 0.95 * len(below),
                  f"the {view} view shows the map in false colour: {on_palette} of {len(below)} "
                  f"pixels of its lower quarter on the palette or grey")
            bar = False
            for row in rows[:height * 3 // 4]:
                places = [palette_place(rgb) for rgb in row[:400]]
                run_start = None
                for x, p in enumerate(places):
                    if p is None:
                        run_start = None
                        continue
                    if run_start is None:
                        run_start = x
                    if x - run_start >= 150 and places[run_start] < 0.1 and p > 0.9:
                        bar = True
                if bar:
                    break
            check(bar, f"the {view} view's panel shows a scale bar through the palette")


def main():
    with tempfile.TemporaryDirectory() as tmp:
        ref = reference_figures(tmp)
        bad_input_writes_nothing(tmp, ref)
        noise_png_has_its_scale(tmp)
        efficiency_map_and_fixed_range(tmp)
        window_maps(tmp)
    sys.exit(exit_code())


if __name__ == "__main__":
    main()
