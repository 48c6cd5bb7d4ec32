"""Shared fixtures of the fspm Python tests."""
import pathlib

import numpy as np
import pytest

import fspm

ROOT = pathlib.Path(__file__).resolve().parents[2]


def chain_tree(segments, radius, length=1.0):
    """A straight chain of internodes up the z axis, all of one radius."""
    z = np.arange(segments + 1, dtype=float) * length
    starts = np.zeros((segments, 3))
    ends = np.zeros((segments, 3))
    starts[:, 2], ends[:, 2] = z[:-1], z[1:]
    parents = np.arange(segments) - 1
    return fspm.Tree.from_arrays(parents, starts, ends, radii=np.full(segments, radius),
                                 birth_times=np.arange(segments, dtype=float))


def forked_tree():
    """A trunk of three internodes (radius 0.05) forking into two branches of two internodes
    (radius 0.01) each."""
    pts = {"o": (0, 0, 0), "a": (0, 0, 1), "b": (0.1, 0, 2), "c": (0.1, 0.1, 3)}
    rows = [(-1, "o", "a", 0.05, 0), (0, "a", "b", 0.05, 0), (1, "b", "c", 0.05, 0)]
    starts = [pts[r[1]] for r in rows]
    ends = [pts[r[2]] for r in rows]
    parents = [r[0] for r in rows]
    radii = [r[3] for r in rows]
    orders = [0, 0, 0]
    for side in (-1, 1):
        d1 = np.add(pts["c"], (0.5 * side, 0, 0.5))
        d2 = d1 + (0.4 * side, 0.1, 0.4)
        parents += [2, len(parents)]
        starts += [pts["c"], d1]
        ends += [d1, d2]
        radii += [0.01, 0.01]
        orders += [1, 1]
    return fspm.Tree.from_arrays(parents, np.array(starts, float), np.array(ends, float),
                                 radii=radii, orders=orders)


@pytest.fixture
def root():
    return ROOT
