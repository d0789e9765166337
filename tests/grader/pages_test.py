#!/usr/bin/env python3
"""The grader's HTML pages in a real browser (headless Chromium), measured, not looked at: a
student's feedback page (index.html, the renders embedded) and a batch's summary.html.

The feedback page is the grader's own, from grading the reference solutions' branching lab as a
student's (the correctness check's six scenes, a furnace among them); the summary is `grader
merge`'s, from a hand-made batch of result.json files whose tallest bar has a count above it.
Each page is loaded with a script appended that writes the layout's measurements into the DOM
(Chromium's --dump-dom prints them), then screenshotted at the same window size. Checked:
- every render is shown at least 192 CSS pixels wide, enlarged by a whole factor, with
  `image-rendering: pixelated` (square, sharp pixels), and shrinks to fit a narrow page;
- every render has a frame: just outside its pixels, on every side, the screenshot is distinctly
  darker than the page, so that the furnace's near-white render shows on the white page;
- every label of the score histogram (counts, ranges, axis title) lies inside its SVG's box.

Usage: pages_test.py --build BUILD [--screenshots DIR] (DIR keeps summary.png and feedback.png).
Skipped (exit 77) without Chromium (Debian's package `chromium`, which scripts/install-deps.sh
installs on Debian).
"""
import html
import json
import os
import pathlib
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import zlib

from support import LABS, arguments, check, exit_code, grader

SKIPPED = 77  # the test's SKIP_RETURN_CODE (tests/CMakeLists.txt)
WINDOW = (1200, 2000)  # CSS pixels: the furnace's row of the feedback page lies inside
NARROW_COLUMN = 200  # CSS pixels: the page's body narrower than a render (Chromium's
                     # narrowest window, 500 pixels, is wider than one)
MIN_RENDER_WIDTH = 192  # CSS pixels: 3x a 64 x 64 grading render, where its noise shows
FRAME_SEARCH = 3  # CSS pixels outside a render where its frame must be; a space, 4 pixels wide,
                  # keeps the next render out of reach
DARKER = 60  # levels of 255 that the frame is darker than the page by, at least
NEAR_WHITE = 225  # the furnace's render, on average, is at least this light

args = arguments((["--screenshots"], {"help": "a folder to keep the pages' screenshots in"}), source=False)
GRADER = grader(args)


# Run at the page's load event, when the embedded images are decoded and laid out. The results go
# into a hidden element, which changes nothing of the layout the screenshot shows.
MEASURE = """<script>
window.addEventListener("load", () => {
  const box = r => ({left: r.left, top: r.top, right: r.right, bottom: r.bottom});
  const images = [...document.images].map(img => {
    const r = img.getBoundingClientRect(), s = getComputedStyle(img);
    const px = name => parseFloat(s[name]) || 0;
    const caption = img.parentElement.previousElementSibling;
    return {scene: caption ? caption.textContent.split(":")[0] : "",
            box: box(r),
            content: {left: r.left + px("borderLeftWidth") + px("paddingLeft"),
                      top: r.top + px("borderTopWidth") + px("paddingTop"),
                      right: r.right - px("borderRightWidth") - px("paddingRight"),
                      bottom: r.bottom - px("borderBottomWidth") - px("paddingBottom")},
            naturalWidth: img.naturalWidth, imageRendering: s.imageRendering};
  });
  const svgs = [...document.querySelectorAll("svg")].map(svg => ({
    box: box(svg.getBoundingClientRect()),
    texts: [...svg.querySelectorAll("text")].map(t => ({text: t.textContent,
                                                       box: box(t.getBoundingClientRect())}))}));
  const out = document.createElement("pre");
  out.id = "pathlab-measurements";
  out.hidden = true;
  out.textContent = JSON.stringify({dpr: devicePixelRatio, width: innerWidth, height: innerHeight,
                                    body: box(document.body.getBoundingClientRect()),
                                    images, svgs});
  document.body.appendChild(out);
});
</script>
"""


def chromium(browser, profile, page, window, *options):
    # --no-sandbox: Chromium's own sandbox refuses to run as root, as CI does.
    command = [browser, "--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
               "--hide-scrollbars", "--no-first-run", f"--user-data-dir={profile}",
               f"--window-size={window[0]},{window[1]}", *options,
               pathlib.Path(page).resolve().as_uri()]
    return subprocess.run(command, capture_output=True, text=True, timeout=120)


def measure(browser, tmp, page, window, screenshot=None, column=None):
    """The page's layout at this window size (and its screenshot, to `screenshot`): the page is
    copied beside itself with MEASURE appended, loaded once for the DOM, once for the picture.
    `column`: the body at most this wide (CSS pixels)."""
    measured = os.path.join(os.path.dirname(page), "measured-" + os.path.basename(page))
    with open(page) as f:
        text = f.read()
    if column:
        text = text.replace("</head>", f"<style>body{{max-width:{column}px}}</style></head>")
    with open(measured, "w") as f:
        f.write(text.replace("</body>", MEASURE + "</body>"))
    profile = os.path.join(tmp, "chromium-profile")
    run = chromium(browser, profile, measured, window, "--dump-dom")
    found = re.search(r'<pre id="pathlab-measurements" hidden="">(.*?)</pre>', run.stdout, re.S)
    if not found:
        raise RuntimeError(f"Chromium did not measure {page}:\n{run.stderr[-2000:]}")
    layout = json.loads(html.unescape(found.group(1)))
    if screenshot:
        run = chromium(browser, profile, measured, window, f"--screenshot={screenshot}")
        if not os.path.exists(screenshot):
            raise RuntimeError(f"Chromium took no screenshot of {page}:\n{run.stderr[-2000:]}")
    os.remove(measured)
    return layout


def read_png(path):
    """(width, height, rows): each row a bytearray of RGB(A) bytes; 8-bit, not interlaced, as
    Chromium writes its screenshots."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    pos, chunks, header = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            chunks.append(body)
    width, height, depth, colour, _, _, interlaced = header
    if depth != 8 or interlaced or colour not in (2, 6):
        raise ValueError(f"{path}: a PNG other than 8-bit RGB(A), not interlaced: {header}")
    bpp = 3 if colour == 2 else 4
    raw = zlib.decompress(b"".join(chunks))
    stride = width * bpp
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        # The PNG specification's filters, undone: each byte was stored minus a prediction from
        # the byte to its left (a), above (b) and above-left (c).
        if kind == 1:
            for i in range(bpp, stride):
                line[i] = (line[i] + line[i - bpp]) & 255
        elif kind == 2:
            line = bytearray((a + b) & 255 for a, b in zip(line, previous))
        elif kind == 3:
            for i in range(stride):
                left = line[i - bpp] if i >= bpp else 0
                line[i] = (line[i] + ((left + previous[i]) >> 1)) & 255
        elif kind == 4:
            for i in range(stride):
                a = line[i - bpp] if i >= bpp else 0
                b, c = previous[i], previous[i - bpp] if i >= bpp else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        previous = line
    if bpp == 4:
        rows = [rgb_of(row) for row in rows]
    return width, height, rows


def rgb_of(rgba):
    rgb = bytearray(len(rgba) // 4 * 3)
    for channel in range(3):
        rgb[channel::3] = rgba[channel::4]
    return rgb


class Screenshot:
    def __init__(self, path):
        self.width, self.height, self.rows = read_png(path)

    def grey(self, x, y):
        """The mean of the pixel's red, green and blue (0-255)."""
        row = self.rows[y]
        return (row[3 * x] + row[3 * x + 1] + row[3 * x + 2]) / 3


def device_rect(rect, dpr):
    """The device pixels wholly inside a CSS rectangle: [x0, x1) x [y0, y1)."""
    return (int(-(-rect["left"] * dpr // 1)), int(rect["right"] * dpr // 1),
            int(-(-rect["top"] * dpr // 1)), int(rect["bottom"] * dpr // 1))


def frame_problems(shot, image, dpr):
    """Where the screenshot shows no frame around `image`: at a quarter, half and three quarters
    along each side, the darkest pixel within FRAME_SEARCH CSS pixels outside the render's pixels
    must be DARKER than the page (the page left of the body's margin, on the render's row)."""
    # Chromium paints a box with its edges rounded to the nearest device pixel.
    c = image["content"]
    x0, x1, y0, y1 = (round(c[side] * dpr) for side in ("left", "right", "top", "bottom"))
    reach = max(1, round(FRAME_SEARCH * dpr))
    page = shot.grey(0, (y0 + y1) // 2)
    problems = []
    for side in ("left", "right", "top", "bottom"):
        for t in (0.25, 0.5, 0.75):
            if side in ("left", "right"):
                y = int(y0 + t * (y1 - y0))
                outside = [(x0 - d, y) if side == "left" else (x1 - 1 + d, y)
                           for d in range(1, reach + 1)]
            else:
                x = int(x0 + t * (x1 - x0))
                outside = [(x, y0 - d) if side == "top" else (x, y1 - 1 + d)
                           for d in range(1, reach + 1)]
            darkest = min(shot.grey(x, y) for x, y in outside)
            if page - darkest < DARKER:
                problems.append(f"{side} at {t}: darkest {darkest:.0f} beside the page's "
                                f"{page:.0f}")
    return problems


def mean_grey(shot, image, dpr):
    x0, x1, y0, y1 = device_rect(image["content"], dpr)
    values = [shot.grey(x, y) for y in range(y0, y1) for x in range(x0, x1)]
    return sum(values) / max(1, len(values))


def inside(rect, outer):
    return (rect["left"] >= outer["left"] and rect["right"] <= outer["right"]
            and rect["top"] >= outer["top"] and rect["bottom"] <= outer["bottom"])


def result_json(identifier, score, diagnoses=()):
    """A result.json as `grader batch` writes one, with only what the gradebook reads."""
    return {"id": identifier, "status": "graded", "score": score, "max_score": 32,
            "labs": {lab: {"score": score / 4, "max_score": 8}
                     for lab in LABS},
            "diagnoses": [{"lab": lab, "check": "correctness", "diagnosis": d}
                          for lab, d in diagnoses],
            "graded_under": GRADED_UNDER}


# What the hand-made batch was graded under (its batch.json), which every result above shares.
GRADED_UNDER = {"rubric_hash": "0123456789abcdef", "scenes_hash": "fedcba9876543210"}


def make_pages(tmp):
    """(feedback page, summary page): the solutions' branching lab graded into a shard's
    submission s01, four other results written by hand (the 90-100% bar the tallest, with 3),
    and the shard merged into a class's gradebook."""
    shard = os.path.join(tmp, "shard")
    viewer = os.path.join(args.build, "viewer_solutions_as_student")
    run = subprocess.run([GRADER, "--viewer", viewer, "--lab", "branching", "--no-speed",
                          "--html", os.path.join(shard, "submissions", "s01")],
                         capture_output=True, text=True, timeout=600)
    feedback = os.path.join(shard, "submissions", "s01", "index.html")
    if not os.path.exists(feedback):
        raise RuntimeError(f"the grader wrote no feedback page:\n{run.stdout}\n{run.stderr}")
    results = {"s01": result_json("s01", 32), "s02": result_json("s02", 31),
               "s03": result_json("s03", 30),
               "s04": result_json("s04", 20, [("roulette", "biased")]),
               "s05": result_json("s05", 2, [("branching", "direct light only")])}
    for identifier, result in results.items():
        folder = os.path.join(shard, "submissions", identifier)
        os.makedirs(folder, exist_ok=True)
        with open(os.path.join(folder, "result.json"), "w") as f:
            json.dump(result, f)
    with open(os.path.join(shard, "batch.json"), "w") as f:
        json.dump(dict(GRADED_UNDER, max_score=32), f)
    out = os.path.join(tmp, "class")
    run = subprocess.run([GRADER, "merge", shard, "--out", out], capture_output=True, text=True,
                         timeout=60)
    summary = os.path.join(out, "summary.html")
    if run.returncode != 0 or not os.path.exists(summary):
        raise RuntimeError(f"grader merge wrote no summary page:\n{run.stdout}\n{run.stderr}")
    return os.path.join(out, "submissions", "s01", "index.html"), summary


def check_feedback(browser, tmp, page, screenshot):
    layout = measure(browser, tmp, page, WINDOW, screenshot)
    images, dpr = layout["images"], layout["dpr"]
    check(len(images) >= 12, f"the feedback page shows the renders ({len(images)} images)")
    widths = [i["content"]["right"] - i["content"]["left"] for i in images]
    narrow = [w for w in widths if w < MIN_RENDER_WIDTH]
    check(not narrow, f"every render is at least {MIN_RENDER_WIDTH} CSS pixels wide"
          + (f" (one is {narrow[0]:.0f})" if narrow else ""))
    factors = [w / max(1, i["naturalWidth"]) for w, i in zip(widths, images)]
    uneven = [(w, i["naturalWidth"]) for w, f, i in zip(widths, factors, images)
              if i["naturalWidth"] <= 0 or abs(f - round(f)) > 1e-6]
    check(not uneven, "every render is enlarged by a whole factor, so that its pixels are all one "
          "size" + (f" ({uneven[0][0]:.1f} CSS pixels for {uneven[0][1]})" if uneven else ""))
    blurred = sorted({i["imageRendering"] for i in images} - {"pixelated"})
    check(not blurred, f"every render's image-rendering is pixelated (not {blurred})")

    # The frames, in the screenshot: the furnace's render (the student's and the reference's)
    # is near-white, and outlined all the same; so is every other render in the window.
    shot = Screenshot(screenshot)
    # The window's height differs between Chromium's two runs (--dump-dom reserves room for a
    # browser's bar), which moves nothing on these pages: the width must be the same.
    check(shot.width == round(layout["width"] * dpr),
          f"the screenshot ({shot.width} pixels wide) is of the measured window "
          f"({layout['width']} CSS pixels at {dpr}x)")
    seen = [i for i in images if i["box"]["top"] >= 0 and i["box"]["bottom"] * dpr <= shot.height]
    furnace = [i for i in seen if i["scene"] == "furnace"][:2]
    lightness = [round(mean_grey(shot, i, dpr)) for i in furnace]
    check(len(furnace) == 2 and min(lightness) >= NEAR_WHITE,
          f"the furnace's renders (the student's and the reference's) are in the screenshot where "
          f"the layout puts them, near-white (mean grey {lightness}, at least {NEAR_WHITE})")
    for n, image in enumerate(furnace):
        problems = frame_problems(shot, image, dpr)
        check(not problems, f"the furnace's near-white render {n + 1} has a visible frame on every "
              f"side" + (f" ({'; '.join(problems[:4])})" if problems else ""))
    unframed = [(i["scene"], frame_problems(shot, i, dpr)) for i in seen]
    unframed = [(scene, p) for scene, p in unframed if p]
    check(len(seen) >= 6 and not unframed,
          f"every render in the window ({len(seen)}) has a visible frame"
          + (f" (not {unframed[0][0]}'s: {unframed[0][1][0]})" if unframed else ""))

    # In a column narrower than a render, the renders shrink to fit it, square still.
    layout = measure(browser, tmp, page, WINDOW, column=NARROW_COLUMN)
    body = layout["body"]
    misfits = [i for i in layout["images"]
               if i["box"]["right"] > body["right"] + 0.5 or abs(
                   (i["content"]["right"] - i["content"]["left"])
                   - (i["content"]["bottom"] - i["content"]["top"])) > 1]
    check(body["right"] - body["left"] <= NARROW_COLUMN and not misfits,
          f"in a column {NARROW_COLUMN} CSS pixels wide every render shrinks to fit, square"
          + (f" (one is {misfits[0]['box']})" if misfits else ""))


def check_summary(browser, tmp, page, screenshot):
    layout = measure(browser, tmp, page, WINDOW, screenshot)
    svgs = layout["svgs"]
    check(len(svgs) == 1 + len(LABS) and all(len(s["texts"]) == 21 for s in svgs),
          f"the summary has the totals' histogram and one per lab, each with 21 labels (10 counts, "
          f"10 ranges, the axis title): {[len(s['texts']) for s in svgs]}")
    for svg in svgs:
        outside = [t for t in svg["texts"] if not inside(t["box"], svg["box"])]
        check(not outside, "every label of the histogram lies inside its SVG"
              + "".join(f"; '{t['text']}' at {t['box']} outside {svg['box']}" for t in outside[:3]))
    if svgs:
        counts = [t for t in svgs[0]["texts"] if t["text"] == "3"]
        check(len(counts) == 1 and inside(counts[0]["box"], svgs[0]["box"]),
              "the totals' tallest bar's count (3) is there, inside the SVG")


def main():
    browser = shutil.which("chromium")
    if not browser:
        print("skipped: no Chromium to load the pages in (on Debian, scripts/install-deps.sh "
              "installs it: apt install chromium)")
        return SKIPPED
    start = time.monotonic()
    # In the build folder rather than /tmp, which a Chromium packaged as a snap cannot read.
    with tempfile.TemporaryDirectory(dir=args.build, prefix="pages-test-") as tmp:
        shots = args.screenshots or tmp
        os.makedirs(shots, exist_ok=True)
        feedback, summary = make_pages(tmp)
        check_feedback(browser, tmp, feedback, os.path.join(shots, "feedback.png"))
        check_summary(browser, tmp, summary, os.path.join(shots, "summary.png"))
    print(f"the pages made and checked in {time.monotonic() - start:.0f} s")
    return exit_code()


if __name__ == "__main__":
    sys.exit(main())
