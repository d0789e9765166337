"""PFM images (the viewer's linear-radiance output) and the error measures of the figures.

Standard library only: an image is (width, height, array of floats, RGB interleaved).
"""
import array
import sys


def read_pfm(path):
    """Returns (width, height, pixels) of a colour PFM; pixels is an array('f'), RGB per pixel."""
    with open(path, "rb") as f:
        data = f.read()
    # Header: "PF", width and height, scale (negative: little-endian), each ended by whitespace.
    fields, position = [], 0
    while len(fields) < 4:
        while data[position:position + 1].isspace():
            position += 1
        start = position
        while not data[position:position + 1].isspace():
            position += 1
        fields.append(data[start:position].decode("ascii"))
    position += 1  # the single whitespace character before the raster
    if fields[0] != "PF":
        raise ValueError(f"{path}: not a colour PFM (header {fields[0]!r})")
    width, height, scale = int(fields[1]), int(fields[2]), float(fields[3])
    pixels = array.array("f")
    pixels.frombytes(data[position:position + 12 * width * height])
    if (scale < 0) != (sys.byteorder == "little"):
        pixels.byteswap()
    if len(pixels) != 3 * width * height:
        raise ValueError(f"{path}: truncated raster")
    return width, height, pixels


def mean_squared_error(a, b):
    """Mean over pixels and channels of (a - b)^2, for two images of the same size."""
    if a[:2] != b[:2]:
        raise ValueError(f"images of different sizes: {a[:2]} and {b[:2]}")
    pa, pb = a[2], b[2]
    return sum((x - y) * (x - y) for x, y in zip(pa, pb)) / len(pa)
