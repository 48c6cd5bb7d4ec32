#!/usr/bin/env python3
"""Prints the rows of the every-light-model tables of docs/evaluation.md from a result directory
of examples/experiments/adapted_vs_grown_local_models.toml or adapted_vs_grown_sky.toml: per light model, tropism pairing, type and age the
ratios of the sets' mean internodes (G / O, T / O), the mean distances of the four groups and the
p-values of the two t-tests.

    python3 scripts/avg_models_table.py avg-local [path/to/fspm-full]
"""
import collections
import csv
import subprocess
import sys


def set_sizes(out_dir, fspm):
    """Mean internodes per (light model, pairing, preset, years, set) over the successful runs."""
    text = subprocess.run([fspm, "results", "export", out_dir, "--csv"], capture_output=True,
                          text=True, check=True).stdout
    sizes = collections.defaultdict(list)
    for r in csv.DictReader(text.splitlines()):
        if r["status"] == "ok":
            key = (r["light_model"], r["preset_tropisms"], r["preset"], r["years"], r["set"])
            sizes[key].append(float(r["internodes"]))
    return {k: sum(v) / len(v) for k, v in sizes.items()}


def t_tests(out_dir):
    """The rows of ttests.csv by (group key, first comparison)."""
    tests = {}
    with open(f"{out_dir}/ttests.csv", newline="") as f:
        for t in csv.DictReader(f):
            g = dict(kv.split("=", 1) for kv in t["group"].split(", "))
            key = (g["light_model"], g["preset_tropisms"], g["preset"], g["years"])
            tests[(key, t["a"])] = t
    return tests


def p_text(p, smaller):
    p = float(p)
    text = "< 0.001" if p < 0.001 else (f"{p:.3f}" if p < 0.01 else f"{p:.2f}")
    return text + (" (smaller)" if smaller and p < 0.05 else "")


def main():
    out_dir = sys.argv[1]
    fspm = sys.argv[2] if len(sys.argv) > 2 else "fspm"
    size = set_sizes(out_dir, fspm)
    tests = t_tests(out_dir)
    keys = sorted({k for (k, _) in tests}, key=lambda k: (k[0], k[1] != "text", k[2], int(k[3])))
    for k in keys:
        o, g, t = (size[k + (s,)] for s in ("O", "G", "T"))
        tg, to = tests[(k, "T-G")], tests[(k, "T-O")]
        tg_smaller = float(tg["mean_a"]) < float(tg["mean_b"])
        # Raw distances run into the thousands, normalized ones lie in [0, 1].
        d = (lambda v: f"{float(v):.3f}") if tg.get("distance") == "normalized" else (lambda v: f"{float(v):.0f}")
        print(f"| {k[0]} | {k[1]} | {k[2]}, {k[3]} y | {g / o:.2f} | {t / o:.2f} | "
              f"{d(tg['mean_a'])} | {d(tg['mean_b'])} | {p_text(tg['p'], tg_smaller)} | "
              f"{d(to['mean_a'])} | {d(to['mean_b'])} | {p_text(to['p'], False)} |")


if __name__ == "__main__":
    main()
