#!/usr/bin/env python3
"""Prune a text tree file (fspm-tree 1) like a street tree: remove every branch that leaves the
trunk below a height, with everything it carries. The trunk follows the thickest internode child
from the root (as `fspm stages` does by default).

    scripts/prune_below.py IN.tree HEIGHT_M OUT.tree

Ids are renumbered keeping their order (parents before children), as the format requires.
"""
import sys


def read(source):
    with open(source) as f:
        lines = f.read().splitlines()
    header, nodes = [], []
    for line in lines:
        cols = line.split()
        (nodes if cols and cols[0].isdigit() else header).append(cols if cols and cols[0].isdigit()
                                                                 else line)
    return header, nodes


def trunk(nodes):
    children = {}
    for cols in nodes:
        if cols[1] != "-" and cols[2] == "internode":
            children.setdefault(int(cols[1]), []).append(int(cols[0]))
    radius = {int(cols[0]): float(cols[15]) for cols in nodes}
    path, node = {0}, 0
    while node in children:
        node = max(children[node], key=lambda c: radius[c])
        path.add(node)
    return path


def main(source, height_m, target):
    header, nodes = read(source)
    on_trunk = trunk(nodes)
    new_id, kept = {}, []
    for cols in nodes:
        node, start_z = int(cols[0]), float(cols[7])
        parent = -1 if cols[1] == "-" else int(cols[1])
        if parent >= 0 and parent not in new_id:
            continue  # under a removed branch
        if parent in on_trunk and node not in on_trunk and start_z < height_m:
            continue  # a branch (or organ) off the trunk below the height
        new_id[node] = len(kept)
        cols = [str(new_id[node]), str(new_id[parent]) if parent >= 0 else "-"] + cols[2:]
        kept.append(" ".join(cols))
    out = [f"nodes {len(kept)}" if line.startswith("nodes ") else line for line in header]
    with open(target, "w") as f:
        f.write("\n".join(out + kept) + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(sys.argv[1], float(sys.argv[2]), sys.argv[3])
