#!/usr/bin/env python3
"""Writes the example landscape's heightfield and class map (standard library only).

hills.png: 129 x 129 16-bit grey heights in [0, 1] (6 m per pixel, 150 m per unit in the scene):
a slope rising to the north with two rounded hills and a valley running north-south.
classes.png: 65 x 65 8-bit grey classes stretched over the same terrain: 255 forest on the
slopes, 128 open woodland in the valley floor, 0 a treeless meadow and a path.
"""
import math
import struct
import zlib


def write_png(path, width, height, rows, bit_depth):
    """Greyscale PNG; rows: lists of integers, row 0 at the top."""
    raw = bytearray()
    for row in rows:
        raw.append(0)  # no filter
        for v in row:
            raw += struct.pack(">H", v) if bit_depth == 16 else bytes([v])

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", width, height, bit_depth, 0, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
                chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b""))


def height(u, v):
    """u east, v north, both in [0, 1]; a height in about [0, 1]."""
    slope = 0.45 * v
    hill_a = 0.40 * math.exp(-((u - 0.25) ** 2 + (v - 0.70) ** 2) / 0.03)
    hill_b = 0.30 * math.exp(-((u - 0.78) ** 2 + (v - 0.45) ** 2) / 0.04)
    valley = -0.12 * math.exp(-((u - 0.52) ** 2) / 0.006)
    ripple = 0.03 * math.sin(9 * u + 4 * v) * math.cos(7 * v - 3 * u)
    return max(0.0, min(1.0, 0.08 + slope + hill_a + hill_b + valley + ripple))


def terrain_class(u, v):
    if abs(u - 0.52) < 0.05:
        return 128  # open woodland along the valley floor
    if (u - 0.62) ** 2 + (v - 0.18) ** 2 < 0.012:
        return 0  # a meadow
    if abs(v - (0.88 - 0.3 * u)) < 0.012:
        return 0  # a path across the slope
    return 255


def main():
    n = 129
    rows = [[round(65535 * height(i / (n - 1), 1 - j / (n - 1))) for i in range(n)]
            for j in range(n)]
    write_png("hills.png", n, n, rows, 16)
    m = 65
    rows = [[terrain_class((i + 0.5) / m, 1 - (j + 0.5) / m) for i in range(m)] for j in range(m)]
    write_png("classes.png", m, m, rows, 8)


if __name__ == "__main__":
    main()
