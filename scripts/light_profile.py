#!/usr/bin/python3
"""Mean `light` of a tree's leaf clusters and of its buds (internodes with a value) per height
fifth, bottom to top, read from an fspm `.tree` file (docs/formats.md).

    fspm grow --preset A --years 20 -o a.tree
    scripts/light_profile.py a.tree
"""
import math
import sys


def fifths(rows):
    rows.sort()
    n = len(rows)
    out = []
    for f in range(5):
        part = rows[n * f // 5:n * (f + 1) // 5]
        out.append(sum(v for _, v in part) / len(part) if part else float("nan"))
    return out


def main(path):
    leaves, buds = [], []
    columns = None
    with open(path) as f:
        for line in f:
            if line.startswith("# id "):
                columns = line[2:].split()
                continue
            if columns is None or line.startswith("#") or not line.strip():
                continue
            fields = line.split()
            row = dict(zip(columns, fields))
            light = float(row["light"])
            if math.isnan(light):
                continue
            z = float(row["sz"])
            (leaves if row["kind"] == "leaf" else buds).append((z, light))
    if not leaves:
        sys.exit(f"{path}: no leaf clusters with a light value")
    print("leaf clusters:", " ".join(f"{v:.2f}" for v in fifths(leaves)))
    if buds:
        print("buds:         ", " ".join(f"{v:.2f}" for v in fifths(buds)))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
